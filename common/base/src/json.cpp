// The JSON writer; see json.hpp.
#include "t10/json.hpp"

#include "t10/file.hpp"

namespace t10 {

std::string jsonText(const nlohmann::json& value) {
    return value.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string jsonQuoted(std::string_view text) {
    return nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void writeJsonFile(const std::string& path, const nlohmann::json& value) {
    const std::string text = jsonText(value);
    writeFileAtomically(path, text.data(), text.size(), "JSON");
}

} // namespace t10
