// A shader's errors as lines of the student's file; see shader_messages.hpp.
#include "t10/shader_messages.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace t10 {

namespace {

std::string hexByte(unsigned char byte) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02x", byte);
    return text;
}

// The length of the UTF-8 sequence starting at `s[i]`, or 0 when it is not a valid one.
std::size_t sequenceLength(std::string_view s, std::size_t i) {
    const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = at(i);
    if (lead < 0x80) return 1;
    // The lead byte's length, the smallest code point that needs it (shorter forms are overlong) and its bits.
    struct Form {
        unsigned char mask, value;
        std::size_t length;
        unsigned minimum;
    };
    static constexpr Form kForms[] = {{0xe0, 0xc0, 2, 0x80}, {0xf0, 0xe0, 3, 0x800}, {0xf8, 0xf0, 4, 0x10000}};
    const Form* form = nullptr;
    for (const Form& f : kForms) {
        if ((lead & f.mask) == f.value) form = &f;
    }
    if (form == nullptr) return 0;
    const std::size_t length = form->length;
    const unsigned minimum = form->minimum;
    unsigned code = lead & static_cast<unsigned char>(~form->mask);
    if (i + length > s.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((at(i + k) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (at(i + k) & 0x3fu);
    }
    if (code < minimum || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
    return length;
}

std::string trimmed(std::string_view text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return std::string(text.substr(begin, end - begin));
}

// Reads the decimal number at text[i], moving i past it; -1 when there is none (or it is absurd).
// ANGLE writes -1 for "no line" ("ERROR: -1:-1: '' : Missing main()"): read as 0, the file as a whole.
long readNumber(std::string_view text, std::size_t& i) {
    if (text.substr(i, 2) == "-1") {
        i += 2;
        return 0;
    }
    long value = -1;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
        value = (value < 0 ? 0 : value) * 10 + (text[i] - '0');
        if (value > 100000000) return -1;
        ++i;
    }
    return value;
}

// One line of a compiler's log: its line number (0 when out of the file) and message, or false.
bool logLine(std::string_view text, int lines, ShaderMessage& out) {
    std::size_t i = 0;
    std::string_view rest = text;
    for (std::string_view severity : {"ERROR: ", "error: "}) {
        if (rest.substr(0, severity.size()) == severity) rest.remove_prefix(severity.size());
    }
    // "<string>:<line>" then ": message" (ANGLE) or "(<column>): error: message" (Mesa).
    if (readNumber(rest, i) < 0 || i >= rest.size() || rest[i] != ':') return false;
    ++i;
    const long line = readNumber(rest, i);
    if (line < 0 || i >= rest.size()) return false;
    if (rest[i] == '(') {
        const std::size_t close = rest.find(')', i);
        if (close == std::string_view::npos) return false;
        i = close + 1;
    }
    if (i >= rest.size() || rest[i] != ':') return false;
    std::string message = trimmed(rest.substr(i + 1));
    for (std::string_view severity : {"error: ", "ERROR: "}) {
        if (message.rfind(severity, 0) == 0) message.erase(0, severity.size());
    }
    out.line = line >= 1 && line <= lines ? static_cast<int>(line) : 0;
    out.message = message;
    return true;
}

} // namespace

std::optional<ShaderMessage> utf8Problem(std::string_view bytes) {
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < bytes.size();) {
        const std::size_t length = sequenceLength(bytes, i);
        if (length == 0) {
            return ShaderMessage{line, "byte " + std::to_string(i - lineStart + 1) + " of the line: " +
                                           hexByte(static_cast<unsigned char>(bytes[i])) +
                                           " is not UTF-8 text (save the file as UTF-8; GLSL itself is ASCII "
                                           "outside comments)"};
        }
        if (bytes[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
        i += length;
    }
    return std::nullopt;
}

int lineCount(std::string_view source) {
    return 1 + static_cast<int>(std::count(source.begin(), source.end(), '\n'));
}

std::vector<ShaderMessage> compilerMessages(std::string_view log, int lines) {
    std::vector<ShaderMessage> messages;
    bool unknown = false;
    std::size_t start = 0;
    while (start <= log.size()) {
        std::size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        const std::string text = trimmed(log.substr(start, end - start));
        start = end + 1;
        if (text.empty()) continue;
        ShaderMessage message;
        if (logLine(text, lines, message)) {
            messages.push_back(message);
        } else if (text.find("compilation error") == std::string::npos && text.find("No code generated") == std::string::npos) {
            unknown = true; // a line in no form known here: kept whole below
        }
    }
    if (messages.empty() && (unknown || !trimmed(log).empty())) messages.push_back({0, trimmed(log)});
    return messages;
}

ShaderMessage translatorMessage(std::string_view what, const std::string& file, int lines) {
    std::string_view rest = what;
    if (rest.substr(0, file.size()) == file && rest.size() > file.size() && rest[file.size()] == ':') {
        rest.remove_prefix(file.size() + 1);
        std::size_t i = 0;
        const long line = readNumber(rest, i);
        if (line >= 0 && i < rest.size() && rest[i] == ':')
            return {line >= 1 && line <= lines ? static_cast<int>(line) : 0, trimmed(rest.substr(i + 1))};
    }
    return {0, trimmed(rest)};
}

} // namespace t10
