// The outcome of grading one submission: one enum that the run sets and every output reads
// (report.json, report.html, the gradebook, the class index, the platforms' results), so no output
// compares spellings. statusName gives the word the outputs write.
#pragma once

#include <string>

namespace t10::grade {

enum class Status {
    Graded,       // built, rendered and checked: the score comes from the checks
    Empty,        // the folder holds no file of the part
    MissingFiles, // some of the part's files are missing (and not filled from the reference)
    BuildFailed,  // the compiler or linker refused Tutorial10.cpp
    ShaderError,  // a shader did not compile or link at run time
    Crashed,      // the program failed or left no usable output
    Timeout,      // the program ran past its time limit
    GraderError,  // the grader itself failed: not the student's fault
};

// "graded", "empty", "missing-files", "build-failed", "shader-error", "crashed", "timeout", "grader-error".
inline const char* statusName(Status status) {
    switch (status) {
    case Status::Graded: return "graded";
    case Status::Empty: return "empty";
    case Status::MissingFiles: return "missing-files";
    case Status::BuildFailed: return "build-failed";
    case Status::ShaderError: return "shader-error";
    case Status::Crashed: return "crashed";
    case Status::Timeout: return "timeout";
    case Status::GraderError: return "grader-error";
    }
    return "grader-error";
}

} // namespace t10::grade
