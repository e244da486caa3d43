// The grader's escapers and its one way to write a file; see output.hpp.
#include "report/output.hpp"

#include "t10/file.hpp"

namespace t10::grade {

namespace {

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), 0 when the byte there starts none.
std::size_t sequenceLength(const std::string& text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    if (b < 0x80) return 1;
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xbf; // the range of the second byte
    if (b >= 0xc2 && b <= 0xdf) length = 2;
    else if (b >= 0xe0 && b <= 0xef) {
        length = 3;
        if (b == 0xe0) low = 0xa0;
        if (b == 0xed) high = 0x9f;
    } else if (b >= 0xf0 && b <= 0xf4) {
        length = 4;
        if (b == 0xf0) low = 0x90;
        if (b == 0xf4) high = 0x8f;
    } else {
        return 0;
    }
    if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
    for (std::size_t k = 2; k < length; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
    return length;
}

// A control character other than tab, line feed and carriage return: C0, DEL, or C1 (U+0080-U+009F,
// 0xc2 0x80-0x9f in UTF-8). HTML calls each a parse error; a spreadsheet shows garbage or stops.
bool isControl(const std::string& text, std::size_t i, std::size_t length) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (length == 1) return (b < 0x20 && b != '\t' && b != '\n' && b != '\r') || b == 0x7f;
    return length == 2 && b == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0;
}

} // namespace

std::string validText(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = sequenceLength(text, i);
        if (length == 0 || isControl(text, i, length)) {
            out += "\xef\xbf\xbd"; // U+FFFD, the replacement character
            i += length == 0 ? 1 : length;
        } else {
            out.append(text, i, length);
            i += length;
        }
    }
    return out;
}

std::string htmlEscape(const std::string& raw) {
    const std::string text = validText(raw);
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

std::string csvField(const std::string& raw) {
    const std::string text = validText(raw);
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeOutputFile(const std::string& path, const std::string& content, const std::string& what) {
    writeFileAtomically(path, content.data(), content.size(), what);
}

} // namespace t10::grade
