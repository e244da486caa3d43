// Reading a whole file into memory, with the reason when it cannot be read.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace t10 {

// Reads `path` whole. Throws t10::Error("<path>: cannot open file: <reason>") (or "cannot read
// file") with the system's reason.
std::vector<std::uint8_t> readFile(const std::string& path);

} // namespace t10
