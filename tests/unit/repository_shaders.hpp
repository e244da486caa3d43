// The repository's shaders as the GLSL ES translator's tests meet them (test_glsl_es.cpp, the
// translation; test_glsl_es_validate.cpp, glslangValidator; test_glsl_es_browser.cpp, WebGL 2): the
// list, the reading, and the broken copies that prove each check can fail.
// T10_SHADER_FOLDERS (tests/CMakeLists.txt: the folders below T10_SOURCE_ROOT that hold shaders,
// comma-separated) is the one list of where they are.
#pragma once
#include "t10/file.hpp"
#include "t10/glsl_es.hpp"

#include "t10_catch.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace t10::test {

// The whole file; t10::Error naming the file and the system's reason when it cannot be read.
inline std::string readText(const std::filesystem::path& file) {
    const std::vector<std::uint8_t> bytes = t10::readFile(file.string());
    return std::string(bytes.begin(), bytes.end());
}

// Every .vert and .frag below the shader folders, sorted (found on disk, so a new shader is tested
// without editing a test).
inline std::vector<std::filesystem::path> repositoryShaders() {
    namespace fs = std::filesystem;
    std::vector<fs::path> shaders;
    std::istringstream folders(T10_SHADER_FOLDERS);
    for (std::string folder; std::getline(folders, folder, ',');)
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(T10_SOURCE_ROOT) / folder))
            if (entry.path().extension() == ".vert" || entry.path().extension() == ".frag") shaders.push_back(entry.path());
    std::sort(shaders.begin(), shaders.end());
    return shaders;
}

inline t10::GlslStage stageOf(const std::filesystem::path& file) {
    return file.extension() == ".vert" ? t10::GlslStage::Vertex : t10::GlslStage::Fragment;
}

// The source with an undeclared name appended to the last line that starts with '}' (the end of its
// last function); `line` gets that line's number, where a compiler must report the error.
inline std::string withError(const std::string& source, int& line) {
    std::vector<std::string> lines;
    std::istringstream in(source);
    for (std::string text; std::getline(in, text);) lines.push_back(text);
    std::size_t target = lines.size();
    while (target > 0 && lines[target - 1].rfind('}', 0) != 0) --target;
    REQUIRE(target > 0);
    lines[target - 1] += " float t10Broken = t10UndeclaredName;";
    line = static_cast<int>(target);
    std::string out;
    for (const std::string& text : lines) out += text + "\n";
    return out;
}

// A shader whose #version is its first line (the translator adds `#line 2` after its precisions).
inline const char* const kVersionOnFirstLine = "#version 430 core\nout vec4 c;\n\nvoid main() {\n    c = vec4(1.0);\n}\n";

// Desktop GLSL passed off as ES: the untranslated Part 3 blur (subroutines, binding layouts) with
// only its #version changed. An ES compiler must refuse it.
inline std::string desktopPassedOffAsEs() {
    std::string source = readText(std::filesystem::path(T10_SOURCE_ROOT) / "tutorial10_part3_gaussian/Gauss.frag");
    source.replace(source.find("#version 430 core"), 17, "#version 300 es\nprecision highp float;");
    return source;
}

} // namespace t10::test
