// The checks' one tie to files: a case's buffers read from the folder the stage dumped them into
// (--dump, --output and --capture-passes), as hostile files.
#pragma once
#include "checks/buffers.hpp"

#include <string>

namespace t10::grade {

// Reads <dir>/unit15_level0.pfm and <dir>/frame.png, throwing t10::Error naming a missing or malformed
// one; then every level of units 16 and 17 and the blur passes (<dir>/blur_passes.txt and its
// blur_passNN.pfm), keeping the error of one that cannot be read for the check that reads it.
CaseBuffers loadCaseBuffers(const std::string& dir);

} // namespace t10::grade
