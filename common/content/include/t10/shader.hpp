// Shader manager: finds GLSL files in an ordered list of folders (the stage's folder, then
// common/shaders; --shader-dir goes first), compiles and links them. Any compile or link error
// throws t10::Error with the file name and the driver's log.
#pragma once
#include "t10/gl.hpp"

#include <initializer_list>
#include <string>
#include <vector>

namespace t10 {

struct ProgramLayout;

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

    // A program this manager made, with its files as they were asked for.
    struct Made {
        GLuint program;
        std::vector<std::string> files;
    };
    // The programs made and still alive (a deleted one is dropped when the next is made).
    std::vector<Made> made() const;
    // Links `program` (one of made()) again from its files as they are now, in place: the caller that
    // holds the name keeps drawing with it. The files are linked into a new program first, so an error
    // throws t10::Error (as createProgram) with `program` as it was. A link resets the program's
    // uniform values: the stages set theirs before each draw (uniform blocks, subroutines).
    void relink(GLuint program) const;

private:
    // Compiles `fileNames` and links them into `program`; what the platform sets after linking in `layout`.
    void build(GLuint program, const std::vector<std::string>& fileNames, ProgramLayout& layout) const;

    std::vector<std::string> dirs_;
    mutable std::vector<Made> made_; // the page's shader editing relinks them (shader_edit_web.cpp)
};

} // namespace t10
