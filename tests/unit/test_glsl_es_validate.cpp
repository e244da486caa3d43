// The translator's output is GLSL ES 3.00: glslangValidator (Debian's glslang-tools, the Khronos
// reference compiler) accepts the translation of every shader of the repository, and reports a
// deliberate error on the line of the source that holds it. Built only when CMake finds
// glslangValidator; without it ctest shows the test "glsl es: glslangValidator" as skipped.
#include "t10/glsl_es.hpp"

#include "t10_catch.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

std::vector<fs::path> repositoryShaders() {
    std::vector<fs::path> shaders;
    for (const char* folder : {"common", "extras", "tutorial10_part0_start", "tutorial10_part1_tonemap",
                               "tutorial10_part2_bloom", "tutorial10_part3_gaussian", "tools"})
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(T10_SOURCE_ROOT) / folder))
            if (entry.path().extension() == ".vert" || entry.path().extension() == ".frag") shaders.push_back(entry.path());
    std::sort(shaders.begin(), shaders.end());
    return shaders;
}

struct Result {
    int status;
    std::string log;
};

// Runs glslangValidator on `source` saved as NAME (the extension gives the stage).
Result validate(const std::string& source, const std::string& name) {
    const fs::path dir = fs::path(T10_TEST_TMP_DIR) / "glsl_es";
    fs::create_directories(dir);
    const fs::path file = dir / name;
    std::ofstream(file, std::ios::binary) << source;
    const std::string command = std::string("'") + T10_GLSLANG_VALIDATOR + "' '" + file.string() + "' 2>&1";
    Result result{-1, ""};
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    char buffer[4096];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) result.log.append(buffer, n);
    result.status = pclose(pipe);
    return result;
}

t10::GlslStage stageOf(const fs::path& file) {
    return file.extension() == ".vert" ? t10::GlslStage::Vertex : t10::GlslStage::Fragment;
}

} // namespace

TEST_CASE("glslangValidator accepts the translation of every shader of the repository", "[glsl_es][glslang]") {
    const auto shaders = repositoryShaders();
    REQUIRE(shaders.size() >= 15);
    for (const fs::path& file : shaders) {
        const auto es = t10::translateToGlslEs(readText(file), file.string(), stageOf(file));
        const Result result = validate(es.source, "ok" + file.extension().string());
        INFO(file.string() << "\n" << result.log);
        CHECK(result.status == 0);
    }
}

TEST_CASE("glslangValidator rejects desktop GLSL passed off as ES (the check can fail)", "[glsl_es][glslang]") {
    // The untranslated Part 3 blur with only its #version changed: subroutines, binding layouts.
    std::string source = readText(fs::path(T10_SOURCE_ROOT) / "tutorial10_part3_gaussian/Gauss.frag");
    source.replace(source.find("#version 430 core"), 17, "#version 300 es\nprecision highp float;");
    CHECK(validate(source, "desktop.frag").status != 0);
}

TEST_CASE("a deliberate error on line N of a shader is reported on line N", "[glsl_es][glslang]") {
    // Each repository shader gets an undeclared name on the last line that closes a function; and a
    // shader whose #version is its first line (the translator adds `#line 2` there).
    std::vector<std::pair<std::string, std::string>> sources; // name, source
    for (const fs::path& file : repositoryShaders()) sources.emplace_back(file.string(), readText(file));
    sources.emplace_back("first-line.frag", "#version 430 core\nout vec4 c;\n\nvoid main() {\n    c = vec4(1.0);\n}\n");
    for (auto& [name, source] : sources) {
        std::vector<std::string> lines;
        std::istringstream in(source);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        std::size_t target = lines.size();
        while (target > 0 && lines[target - 1].rfind('}', 0) != 0) --target;
        REQUIRE(target > 0);
        lines[target - 1] += " float t10Broken = t10UndeclaredName;";
        std::string broken;
        for (const std::string& line : lines) broken += line + "\n";
        const fs::path file(name);
        const auto es = t10::translateToGlslEs(broken, name, stageOf(file));
        const Result result = validate(es.source, "broken" + file.extension().string());
        INFO(name << "\n" << result.log);
        CHECK(result.status != 0);
        CHECK_THAT(result.log, Catch::Contains(":" + std::to_string(target) + ": 't10UndeclaredName' : undeclared identifier"));
    }
}
