// Shader manager: finds GLSL files in an ordered list of folders (the stage's folder, then
// common/shaders; --shader-dir goes first), compiles and links them. Any compile or link error
// throws t10::Error with the file name and the driver's log.
#pragma once
#include "t10/gl.hpp"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace t10 {

class ShaderManager {
public:
    explicit ShaderManager(std::vector<std::filesystem::path> searchDirs);

    // Resolves a file name against the search folders; throws t10::Error naming every folder tried.
    std::filesystem::path find(const std::string& fileName) const;

    // Compiles each file (stage from the extension: .vert .frag .geom .comp .tesc .tese) and links
    // them. Returns a raw program name that the caller deletes with glDeleteProgram, as the
    // tutorial's GL_Quit does.
    GLuint createProgram(std::initializer_list<std::string> fileNames) const;
    GLuint createProgram(const std::vector<std::string>& fileNames) const;


private:
    std::vector<std::filesystem::path> dirs_;
};

} // namespace t10
