// What grader/CMakeLists.txt precompiles for the grader's builds of submissions (t10/app.hpp.gch):
// a stage's first include. Compiled from this file rather than from the header itself, which would
// warn "#pragma once in main file".
#include "t10/app.hpp"
