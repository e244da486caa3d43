// The platforms' result files; see formats.hpp. Contracts as their public documentation states them:
// Gradescope's autograder results.json, PrairieLearn's external grading results (1 MB at most) and
// GitHub Classroom's autograding-grading-reporter (a step output holding base64 JSON, version 1).
#include "platforms/formats.hpp"

#include "report/output.hpp"
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/json.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace t10::grade {

namespace {

namespace fs = std::filesystem;

// PrairieLearn rejects results over 1 MB: images are added while the file stays under this many bytes
// (each text field is capped below, so the text alone stays far under it).
constexpr std::size_t kPrairieLearnLimit = 1000 * 1000;
// Gradescope states no size for results.json; a large one loads slowly on every student's page. The
// grader holds it to 500 kB: images take at most 300 kB of it, and the text, every field capped below,
// stays far under the rest (36 steps of 4 KiB at most, the summary 16 KiB twice).
constexpr std::size_t kGradescopeLimit = 500 * 1000;
constexpr std::size_t kGradescopeImageBudget = 300 * 1000;
// Student-facing text: a compiler's full log can run to megabytes; the report keeps all of it.
constexpr std::size_t kMessageCap = 16 * 1024;
constexpr std::size_t kTestOutputCap = 4 * 1024;
// GitHub Classroom's reporter reads the base64 result from one environment variable, and Linux refuses
// a single one over 128 KiB: a failed step's message is kept short (36 steps stay under 60 KiB).
constexpr std::size_t kClassroomMessageCap = 1024;

std::string capped(const std::string& text, std::size_t cap) {
    if (text.size() <= cap) return text;
    return text.substr(0, cap) + "\n[... " + std::to_string(text.size() - cap) + " more bytes: see report.html]";
}

std::string number(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string stepsText(const std::vector<int>& steps) {
    std::string out;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        std::size_t j = i;
        while (j + 1 < steps.size() && steps[j + 1] == steps[j] + 1) ++j;
        out += (out.empty() ? "" : ", ") + std::to_string(steps[i]);
        if (j > i) out += "-" + std::to_string(steps[j]);
        i = j;
    }
    return out;
}

// What the student reads first: the status, the score and every failed check with its diagnosis.
std::string platformSummary(const Report& report) {
    std::ostringstream out;
    out << "Tutorial 10 Part " << report.part << ": " << statusName(report.status) << ", score " << report.score() << "/100";
    if (report.status == Status::Graded) {
        out << " (" << report.passedCount() << " of " << report.checks.size() << " checks passed).\n";
        for (const Check& c : report.checks) {
            if (c.passed) continue;
            out << "FAILED " << c.id << " (steps " << stepsText(c.steps) << "): " << c.diagnosis << "\n";
        }
    } else {
        out << ".\n" << report.message << "\n";
    }
    return capped(out.str(), kMessageCap);
}

std::string checkText(const Check& c) {
    std::ostringstream out;
    if (c.passed) {
        out << "passed " << c.id << ": " << c.measured << "\n";
    } else {
        out << "FAILED " << c.id << ": " << c.diagnosis << "\n  measured: " << c.measured << "\n  tolerance: " << c.tolerance
            << "\n";
    }
    return out.str();
}

std::string stepOutput(const Report& report, const StepResult& step) {
    if (step.checks.empty()) return "not graded: the submission's status is " + std::string(statusName(report.status)) + " (see the summary)";
    std::string out = step.note.empty() ? "" : step.note + "\n";
    // Failures first: they are what the student acts on.
    for (const Check* c : step.checks)
        if (!c->passed) out += checkText(*c);
    for (const Check* c : step.checks)
        if (c->passed) out += checkText(*c);
    return capped(out, kTestOutputCap);
}

// Only what failed: the reporter prints the message of every failed test in the job's log.
std::string failures(const Report& report, const StepResult& step) {
    if (step.checks.empty()) return "not graded: the submission's status is " + std::string(statusName(report.status));
    std::string out;
    for (const Check* c : step.checks)
        if (!c->passed) out += c->id + ": " + c->diagnosis + "\n";
    return capped(out, kClassroomMessageCap);
}

std::string stepName(const Report& report, int step) {
    return "Part " + std::to_string(report.part) + " step " + std::to_string(step);
}

std::string stepNumber(int step) { return std::to_string(step); }

std::string readBinary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string base64(const std::string& bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += kAlphabet[v & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += two ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

// A PNG of the report folder as a JPEG data URI, about a quarter of the PNG's size (the grader's frames
// are noisy renders and heat-maps, which PNG compresses poorly). Quality 90: a picture to look at; the
// checks measured the PNGs, which report.html shows.
constexpr int kJpegQuality = 90;
std::string jpegDataUri(const std::string& path) {
    const std::vector<std::uint8_t> jpeg = encodeJpeg(readPng(path), kJpegQuality, path);
    return "data:image/jpeg;base64," + base64(std::string(jpeg.begin(), jpeg.end()));
}

// The PNG files of a failed image check, labelled for the student.
std::vector<std::pair<std::string, std::string>> checkImages(const Check& c) {
    return {{"your frame", c.studentImage}, {"the reference", c.referenceImage}, {"the difference (heat-map)", c.heatMap}};
}

// Gradescope's top-level output as HTML: the summary, then each failed image check with the student's
// frame, the reference and the heat-map inline (JPEG data URIs, shown at 320 pixels wide: the grader's
// frames are 160 pixels wide at most, about 10 kB each as JPEG). An image already shown (a frame and a
// FLIP check of one case show the same student frame) is named, not repeated; images that would take
// the result past kGradescopeImageBudget are named as left out (report.html has every one).
std::string gradescopeHtml(const Report& report, const std::string& dir) {
    std::string html = "<pre>" + htmlEscape(platformSummary(report)) + "</pre>\n";
    std::map<std::string, std::string> shown; // data URI -> where it was first shown
    std::string omitted;
    std::size_t imageBytes = 0;
    for (const Check& c : report.checks) {
        if (c.passed || c.heatMap.empty()) continue;
        std::string row;
        for (const auto& [label, file] : checkImages(c)) {
            std::error_code error;
            const fs::path path = fs::path(dir) / file;
            if (file.empty() || !fs::is_regular_file(path, error)) continue;
            const std::string url = jpegDataUri(path.string());
            const std::string caption = "<br><small>" + htmlEscape(label) + "</small>";
            const auto before = shown.find(url);
            if (before != shown.end()) {
                row += "<td>(" + htmlEscape(label) + ": as in " + htmlEscape(before->second) + ")</td>";
                continue;
            }
            if (imageBytes + url.size() > kGradescopeImageBudget) {
                omitted += (omitted.empty() ? "" : ", ") + c.id + ": " + label;
                row += "<td>(" + htmlEscape(label) + ": left out, see report.html)</td>";
                continue;
            }
            imageBytes += url.size();
            shown.emplace(url, c.id);
            row += "<td><img src=\"" + url + "\" alt=\"" + htmlEscape(c.id + ": " + label) +
                   "\" style=\"width:320px;image-rendering:pixelated\">" + caption + "</td>";
        }
        html += "<h4>" + htmlEscape(c.id) + "</h4>\n<p>" + htmlEscape(c.diagnosis) + "<br><small>measured: " +
                htmlEscape(c.measured) + "</small></p>\n<table><tr>" + row + "</tr></table>\n";
    }
    if (!omitted.empty()) html += "<p>Images left out to keep the result small: " + htmlEscape(omitted) + " (they are in report.html).</p>\n";
    return html;
}

std::string gradescope(const Report& report, const std::string& dir) {
    std::ostringstream out;
    // `score` is given, so Gradescope shows report.json's score; the tests' points add up to it.
    out << "{\n  \"score\": " << report.score() << ",\n  \"execution_time\": " << static_cast<long>(std::lround(report.seconds))
        << ",\n  \"output\": " << jsonQuoted(gradescopeHtml(report, dir)) << ",\n  \"output_format\": \"html\""
        << ",\n  \"visibility\": \"visible\",\n  \"stdout_visibility\": \"hidden\",\n  \"tests\": [";
    const std::vector<StepResult> steps = stepResults(report.scored());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const StepResult& s = steps[i];
        out << (i ? "," : "") << "\n    {\"name\": " << jsonQuoted(stepName(report, s.step)) << ", \"number\": \""
            << stepNumber(s.step) << "\", \"score\": " << s.points << ", \"max_score\": " << s.maxPoints
            << ", \"status\": \"" << (s.passed ? "passed" : "failed") << "\", \"output\": " << jsonQuoted(stepOutput(report, s))
            << ", \"output_format\": \"text\", \"visibility\": \"visible\", \"tags\": [\"part" << report.part << "\", \"step-"
            << stepNumber(s.step) << "\"]}";
    }
    out << "\n  ]\n}\n";
    std::string text = out.str();
    if (text.size() > kGradescopeLimit) throw Error("the Gradescope result of " + report.submission + " is " +
                                                    std::to_string(text.size()) + " bytes, over the " +
                                                    std::to_string(kGradescopeLimit) + " this grader holds it to");
    return text;
}

std::string prairieLearn(const Report& report, const std::string& dir) {
    const bool gradable = report.status != Status::GraderError;
    std::ostringstream tests;
    const std::vector<StepResult> steps = stepResults(report.scored());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const StepResult& s = steps[i];
        std::string ids, message;
        for (const Check* c : s.checks) {
            ids += (ids.empty() ? "" : ", ") + c->id;
            if (!c->passed) message += (message.empty() ? "" : "\n") + c->id + ": " + c->diagnosis;
        }
        if (s.checks.empty()) message = "not graded (" + std::string(statusName(report.status)) + ")";
        tests << (i ? "," : "") << "\n    {\"name\": " << jsonQuoted(stepName(report, s.step)) << ", \"description\": "
              << jsonQuoted(ids.empty() ? "no checks ran" : "checks: " + ids) << ", \"points\": " << s.points
              << ", \"max_points\": " << s.maxPoints << ", \"message\": "
              << jsonQuoted(capped(message.empty() ? "passed" : message, kTestOutputCap)) << ", \"output\": "
              << jsonQuoted(stepOutput(report, s)) << "}";
    }
    // Frames and heat-maps of failed image checks, once each (a FLIP check covers every step, so they
    // go in the top-level images, not in each test), as PNG data URIs while they fit.
    // The text's size, with room for the note on left-out images and the images' labels.
    const std::size_t textBytes = tests.str().size() + 3 * platformSummary(report).size() + 8 * 1024;
    const std::size_t imageBudget = kPrairieLearnLimit > textBytes ? kPrairieLearnLimit - textBytes : 0;
    std::string images, omitted;
    std::set<std::string> seen;  // a frame and a FLIP check of one case show the same student frame
    std::size_t imageBytes = 0;
    for (const Check& c : report.checks) {
        if (c.passed || c.heatMap.empty()) continue;
        const std::pair<const char*, const std::string*> files[] = {
            {"frame", &c.studentImage}, {"reference", &c.referenceImage}, {"difference heat-map", &c.heatMap}};
        for (const auto& [what, file] : files) {
            std::error_code error;
            const fs::path path = fs::path(dir) / *file;
            if (file->empty() || !fs::is_regular_file(path, error)) continue;
            const std::string url = "data:image/png;base64," + base64(readBinary(path.string()));
            const std::string label = c.id + ": " + what;
            if (!seen.insert(url).second) continue;
            if (imageBytes + url.size() + label.size() + 32 > imageBudget) {
                omitted += (omitted.empty() ? "" : ", ") + label;
                continue;
            }
            imageBytes += url.size() + label.size() + 32;
            images += std::string(images.empty() ? "" : ",") + "\n    {\"label\": " + jsonQuoted(label) + ", \"url\": \"" + url + "\"}";
        }
    }
    std::string output = platformSummary(report);
    if (!omitted.empty()) output += "\nImages left out to keep the result under 1 MB: " + omitted + " (they are in report.html).";
    std::ostringstream out;
    out << "{\n  \"gradable\": " << (gradable ? "true" : "false") << ",\n  \"score\": " << number(report.score() / 100.0, 2);
    if (!gradable) out << ",\n  \"format_errors\": [" << jsonQuoted(capped(report.message, kMessageCap)) << "]";
    out << ",\n  \"message\": " << jsonQuoted(output.substr(0, output.find('\n'))) << ",\n  \"output\": " << jsonQuoted(output)
        << ",\n  \"images\": [" << images << (images.empty() ? "" : "\n  ") << "],\n  \"tests\": [" << tests.str()
        << "\n  ]\n}\n";
    std::string text = out.str();
    if (text.size() > kPrairieLearnLimit) throw Error("the PrairieLearn result of " + report.submission + " is " +
                                                      std::to_string(text.size()) + " bytes, over PrairieLearn's 1 MB");
    return text;
}

// What the Classroom reporter prints under a failed step ("Test code:"): each failed check that blames
// it with what was measured and what was expected, then the tutorial's step; for a submission that was
// not graded, the first step carries the status and the tool's own first words.
std::string classroomDetail(const Report& report, const StepResult& step, bool first) {
    if (step.passed) return step.note;
    if (step.checks.empty()) {
        if (!first) return "";
        std::string message = report.message.substr(0, report.message.find("\n\n"));
        return capped("not graded: " + std::string(statusName(report.status)) + (message.empty() ? "" : "\n" + message), kClassroomMessageCap);
    }
    // The first failed check that names a mistake (else the first failed one) in full; the others by id.
    std::string out;
    const Check* shown = nullptr;
    std::string others;
    for (const Check* c : step.checks)
        if (!c->passed && (shown == nullptr || (shown->mistakes.empty() && !c->mistakes.empty()))) shown = c;
    for (const Check* c : step.checks)
        if (!c->passed && c != shown) others += (others.empty() ? "" : ", ") + c->id;
    if (shown != nullptr)
        out += shown->id + ": " + shown->diagnosis + "\nmeasured: " + shown->measured + "\nexpected: " + shown->tolerance + "\n";
    if (!others.empty()) out += "also failing here: " + others + "\n";
    out = capped(out, kClassroomMessageCap);
    if (out.back() != '\n') out += "\n";
    return out + "tutorial: " + stepAnchor(step.step);
}

std::string classroom(const Report& report) {
    // status: pass only at full marks; error for the grader's own failure; fail otherwise (the
    // reporter fails its step on fail or error: grade.yml decides whether the job fails).
    const std::string status = report.status == Status::GraderError ? "error" : report.score() == 100 ? "pass" : "fail";
    const std::vector<int> failed = report.failedSteps();
    const std::vector<StepResult> steps = stepResults(report.scored());
    // The step to fix first: the earliest one a failed check blames (Report::fixFirst), else the first.
    const int fixStep = !failed.empty() ? failed.front() : steps.empty() ? 0 : steps.front().step;
    std::ostringstream out;
    out << "{\"version\": 1, \"status\": \"" << status << "\", \"max_score\": 100, \"tests\": [";
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const StepResult& s = steps[i];
        const std::string testStatus = report.status == Status::GraderError ? "error" : s.passed ? "pass" : "fail";
        const bool fixFirst = !s.passed && s.step == fixStep && report.status != Status::GraderError;
        // The reporter prints the name on the step's line: the points (whole numbers that add up to the
        // score) and which step to fix first are read there.
        const std::string name = stepName(report, s.step) + ": " + std::to_string(s.points) + "/" +
                                 std::to_string(s.maxPoints) + (s.maxPoints == 1 ? " point" : " points") +
                                 (fixFirst ? " - fix this first" : "");
        out << (i ? ", " : "") << "{\"name\": " << jsonQuoted(name) << ", \"status\": \"" << testStatus
            << "\", \"score\": " << s.points << ", \"message\": " << jsonQuoted(failures(report, s))
            << ", \"test_code\": " << jsonQuoted(classroomDetail(report, s, s.step == fixStep))
            << ", \"filename\": \"\", \"line_no\": 0, \"execution_time\": \"" << number(report.seconds, 1) << "s\"}";
    }
    out << "]}\n";
    return out.str();
}

} // namespace

const std::vector<std::string>& formatNames() {
    static const std::vector<std::string> kNames{"gradescope", "prairielearn", "classroom"};
    return kNames;
}

void writeFormats(const Report& report, const std::vector<std::string>& formats, const std::string& dir) {
    if (formats.empty()) return;
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) throw Error(dir + ": cannot create: " + error.message());
    for (const std::string& format : formats) {
        if (format == "gradescope") {
            writeOutputFile(dir + "/gradescope-results.json", gradescope(report, dir), "Gradescope results");
        } else if (format == "prairielearn") {
            writeOutputFile(dir + "/prairielearn-results.json", prairieLearn(report, dir), "PrairieLearn results");
        } else if (format == "classroom") {
            const std::string json = classroom(report);
            writeOutputFile(dir + "/classroom-result.json", json, "Classroom result");
            writeOutputFile(dir + "/classroom-result.b64", base64(json) + "\n", "Classroom result");
        } else {
            throw Error("unknown result format " + format);
        }
    }
}




} // namespace t10::grade
