// The grader's one output layer: how every file it writes for people (report.json, report.html,
// the gradebook, the class index, the platforms' results) escapes text and reaches the disk. JSON
// strings go through common's writer (t10::jsonQuoted: valid UTF-8 whatever bytes a compiler or a
// student's program printed), HTML and CSV through the one escaper each below (valid UTF-8 too), and every file is
// written whole or not at all (t10::writeFileAtomically).
#pragma once

#include <string>

namespace t10::grade {

// `text` as valid UTF-8 without control characters: each byte that starts no well-formed UTF-8
// sequence, and each control character other than tab, line feed and carriage return (C0, DEL, C1),
// becomes U+FFFD. A compiler's or a student's program's output can hold any bytes.
std::string validText(const std::string& text);

// `text` safe in HTML text and in a double-quoted attribute: validText, then & < > " ' become entities.
std::string htmlEscape(const std::string& text);

// `text` as one CSV field (RFC 4180), after validText: quoted, with quotes doubled, when it holds a
// comma, a quote, a line feed or a carriage return; as it is otherwise.
std::string csvField(const std::string& text);

// Writes `content` to `path` through a temporary file renamed into place; throws t10::Error naming
// the file, `what` it is and the system's reason.
void writeOutputFile(const std::string& path, const std::string& content, const std::string& what);

} // namespace t10::grade
