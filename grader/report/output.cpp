// The grader's escapers and its one way to write a file; see output.hpp.
#include "report/output.hpp"

#include "t10/file.hpp"

namespace t10::grade {

std::string htmlEscape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeOutputFile(const std::string& path, const std::string& content, const std::string& what) {
    writeFileAtomically(path, content.data(), content.size(), what);
}

} // namespace t10::grade
