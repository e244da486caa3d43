// The grader's one output layer: how every file it writes for people (report.json, report.html,
// the gradebook, the class index, the platforms' results) escapes text and reaches the disk. JSON
// strings go through common's writer (t10::jsonQuoted: valid UTF-8 whatever bytes a compiler or a
// student's program printed), HTML and CSV through the one escaper each below, and every file is
// written whole or not at all (t10::writeFileAtomically).
#pragma once

#include <string>

namespace t10::grade {

// `text` safe in HTML text and in a double-quoted attribute: & < > " ' become entities.
std::string htmlEscape(const std::string& text);

// `text` as one CSV field (RFC 4180): quoted, with quotes doubled, when it holds a comma, a quote,
// a line feed or a carriage return; as it is otherwise.
std::string csvField(const std::string& text);

// Writes `content` to `path` through a temporary file renamed into place; throws t10::Error naming
// the file, `what` it is and the system's reason.
void writeOutputFile(const std::string& path, const std::string& content, const std::string& what);

} // namespace t10::grade
