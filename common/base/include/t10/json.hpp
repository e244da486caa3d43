// Writing JSON reports (nlohmann::json, Debian's nlohmann-json3-dev): one writer, so every report
// escapes strings the same way and appears whole or not at all.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace t10 {

// `text` as one JSON string literal, quotes included, for writers that lay out their own JSON: the
// same escaping as jsonText (control characters escaped, invalid UTF-8 bytes replaced by U+FFFD),
// so the result is valid JSON and valid UTF-8 whatever bytes `text` holds.
std::string jsonQuoted(std::string_view text);

// `value` as text: two-space indentation, a final newline, non-ASCII kept as UTF-8 (invalid UTF-8
// in a string is replaced by U+FFFD rather than failing the report).
std::string jsonText(const nlohmann::json& value);

// Writes jsonText(value) to `path` through t10::writeFileAtomically; throws t10::Error naming the
// file and the system's reason.
void writeJsonFile(const std::string& path, const nlohmann::json& value);

} // namespace t10
