// Shader manager: finds GLSL files in an ordered list of folders (the stage's folder, then
// common/shaders; --shader-dir goes first), compiles and links them. Any compile or link error
// throws t10::Error with the file name and the driver's log.
#pragma once
#include "t10/gl.hpp"

#include <initializer_list>
#include <string>
#include <vector>

namespace t10 {

class ShaderManager {
public:
    // Folders as strings (as common/ passes paths everywhere), not std::filesystem::path: this header
    // is in every stage's includes, and <filesystem> was a third of a stage's compile time, which
    // every build of a submission pays.
    explicit ShaderManager(std::vector<std::string> searchDirs);

    // Resolves a file name against the search folders; throws t10::Error naming every folder tried.
    std::string find(const std::string& fileName) const;

    // Compiles each file (stage from the extension: .vert .frag .geom .comp .tesc .tese) and links
    // them. Returns a raw program name that the caller deletes with glDeleteProgram, as the
    // tutorial's GL_Quit does.
    GLuint createProgram(std::initializer_list<std::string> fileNames) const;
    GLuint createProgram(const std::vector<std::string>& fileNames) const;


private:
    std::vector<std::string> dirs_;
};

} // namespace t10
