// Whole files: reading one into memory with the reason when it cannot be read, and writing one so
// that it is either complete or not there at all (a temporary file in the same folder, renamed).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace t10 {

// Reads `path` whole. Throws t10::Error("<path>: cannot open file: <reason>") (or "cannot read
// file") with the system's reason.
std::vector<std::uint8_t> readFile(const std::string& path);

// Writes `size` bytes to `path` through a temporary file next to it, checking every write and the
// close, then renames it into place. On failure the temporary file is removed, a file that was at
// `path` before is left as it was, and t10::Error is thrown with "<path>: cannot write <what>: <the
// system's reason>". `what` names the format in the message ("PNG", "EXR", ...).
void writeFileAtomically(const std::string& path, const void* data, std::size_t size, const std::string& what);

} // namespace t10
