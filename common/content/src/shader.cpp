// Shader manager: resolves GLSL files through the search folders, compiles, links, and turns any
// failure into a t10::Error carrying the file name and the driver's log.
#include "t10/shader.hpp"

#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/gl_object.hpp"

#include "platform_parts.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace t10 {

namespace {

GLenum stageFromExtension(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext == ".vert") return GL_VERTEX_SHADER;
    if (ext == ".frag") return GL_FRAGMENT_SHADER;
    if (ext == ".geom") return GL_GEOMETRY_SHADER;
    if (ext == ".comp") return GL_COMPUTE_SHADER;
    if (ext == ".tesc") return GL_TESS_CONTROL_SHADER;
    if (ext == ".tese") return GL_TESS_EVALUATION_SHADER;
    throw Error(file.string() + ": unknown shader stage (use .vert .frag .geom .comp .tesc or .tese)");
}

std::string readText(const std::filesystem::path& file) {
    const std::vector<std::uint8_t> bytes = readFile(file.string()); // the error carries the reason
    return std::string(bytes.begin(), bytes.end());
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

} // namespace

ShaderManager::ShaderManager(std::vector<std::string> searchDirs) : dirs_(std::move(searchDirs)) {}

std::string ShaderManager::find(const std::string& fileName) const {
    std::string tried;
    for (const std::string& dir : dirs_) {
        const std::filesystem::path candidate = std::filesystem::path(dir) / fileName;
        if (std::filesystem::is_regular_file(candidate)) return candidate.string();
        tried += "\n  " + candidate.string();
    }
    throw Error(fileName + ": shader not found; looked for" + tried);
}

GLuint ShaderManager::createProgram(std::initializer_list<std::string> fileNames) const {
    return createProgram(std::vector<std::string>(fileNames));
}

void ShaderManager::build(GLuint program, const std::vector<std::string>& fileNames, ProgramLayout& layout) const {
    std::vector<Shader> shaders;
    std::string names;
    for (const std::string& name : fileNames) {
        const std::filesystem::path file = find(name);
        const std::string source = compiledSource(readText(file), file.string(), stageFromExtension(file), layout);
        Shader shader(glCreateShader(stageFromExtension(file)));
        const char* text = source.c_str();
        glShaderSource(shader.get(), 1, &text, nullptr);
        glCompileShader(shader.get());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) throw Error(file.string() + ": shader compilation failed:\n" + shaderLog(shader.get()));
        glAttachShader(program, shader.get());
        shaders.push_back(std::move(shader));
        names += (names.empty() ? "" : " + ") + file.string();
    }
    glLinkProgram(program);
    for (const Shader& shader : shaders) glDetachShader(program, shader.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) throw Error(names + ": program link failed:\n" + programLog(program));
}

GLuint ShaderManager::createProgram(const std::vector<std::string>& fileNames) const {
    Program program(glCreateProgram());
    ProgramLayout layout; // what the platform sets after linking (platform_parts.hpp)
    build(program.get(), fileNames, layout);
    applyLayout(program.get(), layout);
    // A name GL hands out again replaces the deleted program's entry.
    made_.erase(std::remove_if(made_.begin(), made_.end(),
                               [&](const Made& m) { return m.program == program.get() || glIsProgram(m.program) != GL_TRUE; }),
                made_.end());
    made_.push_back({program.get(), fileNames});
    return program.release();
}

std::vector<ShaderManager::Made> ShaderManager::made() const {
    std::vector<Made> alive;
    for (const Made& m : made_)
        if (glIsProgram(m.program) == GL_TRUE) alive.push_back(m);
    return alive;
}

void ShaderManager::relink(GLuint program) const {
    const auto entry = std::find_if(made_.begin(), made_.end(), [&](const Made& m) { return m.program == program; });
    if (entry == made_.end()) throw Error("program " + std::to_string(program) + " was not made by this shader manager");
    {
        Program trial(glCreateProgram());
        ProgramLayout unused;
        build(trial.get(), entry->files, unused); // throws, leaving `program` alone
    }
    ProgramLayout layout;
    build(program, entry->files, layout);
    applyLayout(program, layout);
}

} // namespace t10
