// Writing JSON reports (nlohmann::json, Debian's nlohmann-json3-dev): one writer, so every report
// escapes strings the same way and appears whole or not at all.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

namespace t10 {

// `value` as text: two-space indentation, a final newline, non-ASCII kept as UTF-8 (invalid UTF-8
// in a string is replaced by U+FFFD rather than failing the report).
std::string jsonText(const nlohmann::json& value);

// Writes jsonText(value) to `path` through t10::writeFileAtomically; throws t10::Error naming the
// file and the system's reason.
void writeJsonFile(const std::string& path, const nlohmann::json& value);

} // namespace t10
