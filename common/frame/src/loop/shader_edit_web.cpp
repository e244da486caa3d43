// The page's shader editing (web build only; the C halves of Module.t10Shaders and
// Module.t10SetShader, whose JavaScript halves are in common/platform/web/workbench.js).
//
// A stage's shader files are those of its folder in the page's file system (T10_STAGE_SHADER_DIR,
// packaged with the page), which the ShaderManager reads at every GL_Init. An edit is checked before
// it replaces anything: its size, UTF-8, its loops (refused at their lines when the page cannot bound
// them: unboundedLoops, glsl_es.hpp, so that no caller of Module.t10SetShader can hang the tab), then
// the same GLSL ES translation the page makes at load (glsl_es.hpp) and WebGL's compiler on the
// translation; any error is answered as {line, message} in
// the student's file (shader_messages.hpp) and the running programs stay as they are. A source that
// compiles is written over the file and only the programs that use it are linked again, in place
// (ShaderManager::relink: the stage keeps its names, textures and other programs; rebuilding the whole
// stage recompiled every program, 1.3-3 s on SwiftShader); if one does not link, the previous source
// is put back and the last good program keeps drawing. A redrawn frame follows an accepted edit.
#include "t10/app.hpp"
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/glsl_es.hpp"
#include "t10/shader.hpp"
#include "t10/shader_messages.hpp"

#include "page_hooks.hpp"

#include <emscripten.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace t10 {

namespace {

bool isShaderFile(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".vert" || ext == ".frag";
}

// The stage's shader files by name, sorted (its folder's .vert and .frag files).
std::vector<std::string> stageShaders(const Stage& stage) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(stage.shaderDir, error)) {
        if (entry.is_regular_file() && isShaderFile(entry.path())) names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string filePath(const Stage& stage, const std::string& file) { return std::string(stage.shaderDir) + "/" + file; }

std::string readText(const std::string& path) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    return std::string(bytes.begin(), bytes.end());
}

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomically(path, text.data(), text.size(), "shader");
}

std::string dump(const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json answer(const std::vector<ShaderMessage>& errors) {
    nlohmann::json list = nlohmann::json::array();
    for (const ShaderMessage& e : errors) list.push_back({{"line", e.line}, {"message", e.message}});
    return {{"ok", errors.empty()}, {"errors", list}};
}

nlohmann::json refusal(const std::string& message) { return answer({{0, message}}); }

// WebGL's compiler on the translation of `source`; the errors in the student's lines.
std::vector<ShaderMessage> compileErrors(const std::string& translated, bool vertex, int lines) {
    const GLuint shader = glCreateShader(vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
    const char* text = translated.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    std::vector<ShaderMessage> errors;
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        errors = compilerMessages(log.c_str(), lines);
        if (errors.empty()) errors.push_back({0, "the shader did not compile (WebGL gave no log)"});
    }
    glDeleteShader(shader);
    return errors;
}

// The edit checked before anything is replaced: the errors, or none.
std::vector<ShaderMessage> precheck(const std::string& file, const std::string& source) {
    if (source.size() > kGlslEsMaxSourceBytes)
        return {{0, file + ": " + std::to_string(source.size()) + " bytes is more than the " +
                        std::to_string(kGlslEsMaxSourceBytes) + " bytes a shader may have here"}};
    if (const std::optional<ShaderMessage> problem = utf8Problem(source)) return {*problem};
    const int lines = lineCount(source);
    const bool vertex = std::filesystem::path(file).extension() == ".vert";
    GlslEsShader translated;
    try {
        // Loops the page cannot bound first: a shader that never ends must not reach the GPU at all.
        if (std::vector<ShaderMessage> loops = unboundedLoops(source, file); !loops.empty()) return loops;
        translated = translateToGlslEs(source, file, vertex ? GlslStage::Vertex : GlslStage::Fragment);
    } catch (const Error& error) {
        return {translatorMessage(error.what(), file, lines)};
    }
    return compileErrors(translated.source, vertex, lines);
}

// The programs that use `file` linked again with it holding `source`, in place (the host's names kept;
// the rest of the stage, its textures and other programs, as they are). On a failure (a link error)
// `previous` is put back and those already linked again are linked with it. Returns the failure's
// message, or "".
std::string replaceAndRelink(const Stage& stage, const std::string& file, const std::string& source,
                             const std::string& previous) {
    const ShaderManager& shaders = page::app()->shaders();
    const std::string path = filePath(stage, file);
    std::vector<GLuint> users;
    for (const ShaderManager::Made& made : shaders.made()) {
        const bool uses = std::any_of(made.files.begin(), made.files.end(),
                                      [&](const std::string& name) { return name == file && shaders.find(name) == path; });
        if (uses) users.push_back(made.program);
    }
    writeText(path, source);
    std::vector<GLuint> relinked;
    try {
        for (GLuint program : users) {
            shaders.relink(program);
            relinked.push_back(program);
        }
        return "";
    } catch (const std::exception& error) {
        const std::string message = error.what();
        writeText(path, previous);
        for (GLuint program : relinked) shaders.relink(program); // the sources that linked before
        return message;
    }
}

nlohmann::json setShader(const std::string& file, const std::string& source) {
    const Stage* stage = page::stage();
    if (stage == nullptr || page::app() == nullptr) return refusal("the stage is not running, so its shaders cannot be changed");
    const std::vector<std::string> files = stageShaders(*stage);
    if (std::find(files.begin(), files.end(), file) == files.end()) {
        std::string names;
        for (const std::string& name : files) names += (names.empty() ? "" : ", ") + name;
        return refusal("\"" + file + "\" is not one of " + stage->name + "'s shader files (" + names + ")");
    }
    const std::vector<ShaderMessage> errors = precheck(file, source);
    if (!errors.empty()) return answer(errors);
    const std::string previous = readText(filePath(*stage, file));
    if (previous == source) {
        page::requestFrame();
        return answer({});
    }
    const std::string failure = replaceAndRelink(*stage, file, source, previous);
    page::requestFrame();
    if (failure.empty()) return answer({});
    // The message names the files of the program that did not link; the line is the program's.
    return refusal(failure + "\n(the previous " + file + " is drawing again)");
}

nlohmann::json shaders() {
    nlohmann::json list = nlohmann::json::array();
    const Stage* stage = page::stage();
    if (stage == nullptr) return list;
    for (const std::string& file : stageShaders(*stage))
        list.push_back({{"file", file}, {"source", readText(filePath(*stage, file))}});
    return list;
}

std::string& sourceBuffer() {
    static std::string buffer;
    return buffer;
}

std::string& result() {
    static std::string text;
    return text;
}

} // namespace

} // namespace t10

// The page's entry points (workbench.js wraps them; a returned string lives until the next call).
extern "C" {

// The most bytes t10_set_shader takes (the translator's bound).
EMSCRIPTEN_KEEPALIVE int t10_shader_max_bytes() { return static_cast<int>(t10::kGlslEsMaxSourceBytes); }

// Where the page writes the `bytes` bytes of the next t10_set_shader's source; null if too many.
EMSCRIPTEN_KEEPALIVE char* t10_shader_buffer(int bytes) {
    if (bytes < 0 || static_cast<std::size_t>(bytes) > t10::kGlslEsMaxSourceBytes) return nullptr;
    t10::sourceBuffer().assign(static_cast<std::size_t>(bytes), '\0');
    return t10::sourceBuffer().data();
}

// {ok, errors: [{line, message}]} as JSON for `file` set to the buffer's bytes.
EMSCRIPTEN_KEEPALIVE const char* t10_set_shader(const char* file) {
    try {
        t10::result() = t10::dump(t10::setShader(file != nullptr ? file : "", t10::sourceBuffer()));
    } catch (const std::exception& error) {
        // Writing the file or rebuilding with the sources that built before failed: the page cannot draw.
        const std::string message = std::string("the shader edit failed: ") + error.what();
        t10::page::fail(message);
        t10::result() = t10::dump(t10::refusal(message));
    }
    return t10::result().c_str();
}

// [{file, source}] as JSON: the stage's shader files as the page now compiles them.
EMSCRIPTEN_KEEPALIVE const char* t10_shaders() {
    try {
        t10::result() = t10::dump(t10::shaders());
    } catch (const std::exception& error) {
        t10::result() = t10::dump(nlohmann::json{{"error", error.what()}});
    }
    return t10::result().c_str();
}

}
