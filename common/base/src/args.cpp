// Command-line values; see args.hpp.
#include "t10/args.hpp"

#include "t10/error.hpp"

#include <cctype>

namespace t10 {

std::pair<int, int> parseSize(const std::string& text, int minimumSide, int maximumSide) {
    const std::string form = "size '" + text + "' is not WIDTHxHEIGHT (for example 1280x720)";
    const auto x = text.find_first_of("xX");
    auto side = [&](const std::string& part) {
        // At most six digits, so std::stoi cannot overflow; no sign, space or suffix.
        if (part.empty() || part.size() > 6 || part.find_first_not_of("0123456789") != std::string::npos) {
            throw UsageError(form);
        }
        const int value = std::stoi(part);
        if (value < minimumSide || value > maximumSide) {
            throw UsageError("size '" + text + "': each side must be from " + std::to_string(minimumSide) + " to " +
                             std::to_string(maximumSide));
        }
        return value;
    };
    if (x == std::string::npos) throw UsageError(form);
    return {side(text.substr(0, x)), side(text.substr(x + 1))};
}

bool hasSuffix(const std::string& name, const std::string& suffix) {
    if (name.size() < suffix.size()) return false;
    std::string tail = name.substr(name.size() - suffix.size());
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == suffix;
}

} // namespace t10
