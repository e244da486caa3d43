// The range check for numeric options; see cli_range.hpp.
#include "t10/cli_range.hpp"

#include "t10/error.hpp"

#include <cstdio>
#include <string>

namespace t10 {

namespace {

// "0.05", "2", "2.95": numbers as a person writes them.
std::string asWritten(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace

CLI::Validator inRange(double lo, double hi, bool integer) {
    const std::string range = "from " + asWritten(lo) + " to " + asWritten(hi);
    return CLI::Validator(
        [lo, hi, integer, range](std::string& text) -> std::string {
            std::size_t used = 0;
            double value = 0.0;
            try {
                value = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            const bool isNumber = used > 0 && used == text.size();
            const bool isInteger = isNumber && text.find_first_not_of("+-0123456789") == std::string::npos;
            if (!isNumber || (integer && !isInteger)) {
                return "'" + text + "' is not " + (integer ? "a whole number" : "a number") + "; it must be " + range;
            }
            // Written this way round, NaN is rejected too.
            if (!(value >= lo && value <= hi)) return "must be " + range + " (got " + text + ")";
            return std::string();
        },
        range);
}

void refuseEmpty(std::initializer_list<const CLI::Option*> options) {
    for (const CLI::Option* option : options) {
        if (option->count() > 0 && option->as<std::string>().empty())
            throw UsageError(option->get_name() + ": the value is empty");
    }
}

std::vector<std::pair<int, int>> parseResizeSequence(
    const std::string& text, const std::function<std::pair<int, int>(const std::string&)>& parseSize) {
    std::vector<std::pair<int, int>> sizes;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty())
            throw UsageError("--resize-sequence " + text + ": size " + std::to_string(sizes.size() + 1) +
                             " is empty (a comma too many?)");
        sizes.push_back(item == "0x0" ? std::pair<int, int>(0, 0) : parseSize(item));
        if (comma == std::string::npos) return sizes;
        start = comma + 1;
    }
}

} // namespace t10
