// The translator's output in the compiler that matters: WebGL 2 in headless Chromium (ANGLE's shader
// translator, on SwiftShader). One page compiles every translation of the repository's shaders, links
// the stages' pairs, and compiles copies with a deliberate error whose line ANGLE must report as the
// source's. Chromium is driven by the repository's one DevTools client (tools/web/cdp.py), through
// tools/web/page_value.py, which serves the page and prints its results as JSON. Built only where
// CMake finds Chromium; elsewhere the test "glsl es: Chromium" is skipped.
#include "t10/glsl_es.hpp"

#include "repository_shaders.hpp"
#include "t10_catch.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace t10::test;

namespace {

bool isVertex(const fs::path& file) { return file.extension() == ".vert"; }

std::string translate(const std::string& source, const fs::path& file) {
    return t10::translateToGlslEs(source, file.string(), isVertex(file) ? t10::GlslStage::Vertex : t10::GlslStage::Fragment)
        .source;
}

// Compiles every case's shader (and links it with `with`, when given) in WebGL 2 and leaves, per
// case, {compiled, linked, log} in window.t10Results.
const char* kPage = R"(<!DOCTYPE html><html><body><script>
const cases = CASES;
const gl = document.createElement("canvas").getContext("webgl2");
const results = [];
function compile(type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  return shader;
}
for (const c of cases) {
  if (!gl) { results.push({compiled: false, linked: false, log: "no WebGL 2"}); continue; }
  const shader = compile(c.vertex ? gl.VERTEX_SHADER : gl.FRAGMENT_SHADER, c.source);
  const r = {compiled: !!gl.getShaderParameter(shader, gl.COMPILE_STATUS), linked: null, log: gl.getShaderInfoLog(shader)};
  if (r.compiled && c.with !== undefined) {
    const program = gl.createProgram();
    gl.attachShader(program, shader);
    gl.attachShader(program, compile(c.vertex ? gl.FRAGMENT_SHADER : gl.VERTEX_SHADER, c.with));
    gl.linkProgram(program);
    r.linked = !!gl.getProgramParameter(program, gl.LINK_STATUS);
    r.log += gl.getProgramInfoLog(program);
  }
  results.push(r);
}
window.t10Results = results;
</script></body></html>
)";

nlohmann::json runInChromium(const nlohmann::json& cases) {
    const fs::path dir = fs::path(T10_TEST_TMP_DIR) / "glsl_es_browser";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string json = cases.dump();
    for (std::size_t at = 0; (at = json.find("</", at)) != std::string::npos; at += 3) json.replace(at, 2, "<\\/");
    std::string page = kPage;
    page.replace(page.find("CASES"), 5, json);
    std::ofstream(dir / "page.html", std::ios::binary) << page;
    const std::string log = (dir / "page_value.log").string();
    const std::string command = std::string("PYTHONPATH='") + T10_TOOLS_DIR + "' '" + T10_PYTHON +
                                "' -m web.page_value --root '" + dir.string() + "' --page page.html --value window.t10Results" +
                                " --renderer swiftshader --timeout 150 --chromium '" + T10_CHROMIUM + "' --log '" +
                                (dir / "chromium.log").string() + "' 2>'" + log + "'";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string text;
    char buffer[4096];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    const int status = pclose(pipe);
    INFO("page_value.py's exit status " << status << "; its messages: " << log << " (and chromium.log beside it):\n"
                                        << readText(log));
    REQUIRE(status == 0);
    return nlohmann::json::parse(text);
}

} // namespace

TEST_CASE("WebGL 2 compiles every translation and reports a deliberate error on the source's line", "[glsl_es][chromium]") {
    const fs::path root(T10_SOURCE_ROOT);
    const std::string quad = translate(readText(root / "common/shaders/FullScreenQuad.vert"), "FullScreenQuad.vert");
    const std::string sceneVertex = translate(readText(root / "common/shaders/Scene.vert"), "Scene.vert");
    nlohmann::json cases = nlohmann::json::array();
    std::vector<std::string> names;
    std::vector<int> errorLines; // 0: must compile (and link when paired)
    const auto add = [&](const std::string& name, const fs::path& file, const std::string& source, int errorLine) {
        nlohmann::json c = {{"vertex", isVertex(file)}, {"source", source}};
        const std::string stage = file.parent_path().filename().string();
        const bool postProcess = stage.rfind("tutorial10_", 0) == 0 || stage == "extras" || stage == "views";
        if (errorLine == 0 && postProcess && !isVertex(file)) c["with"] = quad;
        if (errorLine == 0 && file.filename() == "Scene.frag") c["with"] = sceneVertex;
        cases.push_back(c);
        names.push_back(name);
        errorLines.push_back(errorLine);
    };
    for (const fs::path& file : repositoryShaders()) {
        const std::string source = readText(file);
        add(file.string(), file, translate(source, file), 0);
        int line = 0;
        const std::string broken = withError(source, line);
        add(file.string() + " with an error on line " + std::to_string(line), file, translate(broken, file), line);
    }
    int line = 0;
    const std::string first = withError(kVersionOnFirstLine, line);
    add("#version on line 1, an error on line " + std::to_string(line), "first.frag", translate(first, "first.frag"), line);
    // The check can fail: desktop GLSL under an ES version line does not compile.
    add("untranslated Gauss.frag", "Gauss.frag", desktopPassedOffAsEs(), -1);

    const nlohmann::json results = runInChromium(cases);
    REQUIRE(results.size() == cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const nlohmann::json& r = results[i];
        INFO(names[i] << "\n" << r["log"].get<std::string>());
        if (errorLines[i] == 0) {
            CHECK(r["compiled"].get<bool>());
            if (cases[i].contains("with")) CHECK(r["linked"] == true);
        } else {
            CHECK_FALSE(r["compiled"].get<bool>());
            if (errorLines[i] > 0) CHECK_THAT(r["log"].get<std::string>(), Catch::Contains("0:" + std::to_string(errorLines[i]) + ": 't10UndeclaredName'"));
        }
    }
}
