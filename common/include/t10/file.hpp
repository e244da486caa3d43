// Reading a whole file into memory, with the reason when it cannot be read.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace t10 {

// Reads `path` into `bytes`. On failure returns false and sets `fault` to the reason, e.g.
// "cannot open file: No such file or directory" (without the path: callers put it in front).
bool readFile(const std::string& path, std::vector<std::uint8_t>& bytes, std::string& fault);

} // namespace t10
