// The translator's output is GLSL ES 3.00: glslangValidator (Debian's glslang-tools, the Khronos
// reference compiler) accepts the translation of every shader of the repository, and reports a
// deliberate error on the line of the source that holds it. Built only when CMake finds
// glslangValidator; without it ctest shows the test "glsl es: glslangValidator" as skipped.
#include "t10/glsl_es.hpp"

#include "repository_shaders.hpp"
#include "t10_catch.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace t10::test;

namespace {

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
    CHECK(validate(desktopPassedOffAsEs(), "desktop.frag").status != 0);
}

TEST_CASE("a deliberate error on line N of a shader is reported on line N", "[glsl_es][glslang]") {
    // Each repository shader gets an undeclared name on the last line that closes a function; and a
    // shader whose #version is its first line (the translator adds `#line 2` there).
    std::vector<std::pair<std::string, std::string>> sources; // name, source
    for (const fs::path& file : repositoryShaders()) sources.emplace_back(file.string(), readText(file));
    sources.emplace_back("first-line.frag", kVersionOnFirstLine);
    for (auto& [name, source] : sources) {
        int target = 0;
        const std::string broken = withError(source, target);
        const fs::path file(name);
        const auto es = t10::translateToGlslEs(broken, name, stageOf(file));
        const Result result = validate(es.source, "broken" + file.extension().string());
        INFO(name << "\n" << result.log);
        CHECK(result.status != 0);
        CHECK_THAT(result.log, Catch::Contains(":" + std::to_string(target) + ": 't10UndeclaredName' : undeclared identifier"));
    }
}
