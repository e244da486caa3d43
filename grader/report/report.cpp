// Writing the reports and the gradebook; see report.hpp. Files are written to a temporary name and
// renamed into place, so a report on disk is always complete.
#include "report/report.hpp"

#include "report/output.hpp"
#include "t10/error.hpp"
#include "t10/json.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace t10::grade {

namespace fs = std::filesystem;

namespace {




std::string jsonNumber(const std::vector<double>& values) {
    std::ostringstream out;
    out.precision(6);
    if (values.size() == 1) {
        out << values[0];
        return out.str();
    }
    out << "[";
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
    out << "]";
    return out.str();
}

std::string stepList(const std::vector<int>& steps) {
    std::string out;
    for (std::size_t i = 0; i < steps.size(); ++i) out += (i ? ", " : "") + std::to_string(steps[i]);
    return out;
}


} // namespace

int Report::passedCount() const {
    int passed = 0;
    for (const Check& check : checks) passed += check.passed ? 1 : 0;
    return passed;
}

std::vector<int> Report::failedSteps() const { return blamedSteps(checks); }

Scored Report::scored() const { return {part, rubric, status == Status::Graded, checks}; }

int Report::score() const { return grade::score(scored()); }

namespace {

// The first failed check that blames `step`, preferring one that names a mistake.
const Check* blamedBy(const Report& report, int step) {
    const Check* first = nullptr;
    for (const Check& check : report.checks) {
        const std::vector<int> steps = failedSteps(check);
        if (std::find(steps.begin(), steps.end(), step) == steps.end()) continue;
        if (!check.mistakes.empty()) return &check;
        if (first == nullptr) first = &check;
    }
    return first;
}

} // namespace

std::string stepAnchor(int step) {
    const char* url = std::getenv("T10_GRADE_TUTORIAL_URL");
    return std::string(url != nullptr && *url != '\0' ? url : "tutorial10.html") + "#step-" + std::to_string(step);
}

namespace {

// `path` as the student knows it: without the submission folder's name in front.
std::string inSubmission(const std::string& path, const std::string& submission) {
    const std::string prefix = submission + "/";
    return path.compare(0, prefix.size(), prefix) == 0 ? path.substr(prefix.size()) : path;
}

// The first error of a compiler's or a shader compiler's output, as "FILE:LINE: error: ...", FILE
// relative to the submission; "" when the output names none. GCC writes "FILE:LINE:COL: error: ...";
// Mesa writes "SOURCE:LINE(COL): error: ..." (or "preprocessor error") under the line of the
// program's error that names the shader file.
std::string firstError(const std::string& output, const std::string& submission) {
    static const std::regex gcc(R"(^(\S+?):(\d+):(?:\d+:)? (?:fatal )?error: (.*)$)");
    static const std::regex shaderFile(R"((\S+\.(?:frag|vert|geom|comp|tesc|tese|glsl)):)");
    static const std::regex mesa(R"(^\s*\d+:(\d+)\(\d+\): ((?:preprocessor )?error: .*)$)");
    std::string shader;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        std::smatch match;
        if (std::regex_search(line, match, gcc)) return inSubmission(match[1], submission) + ":" + match[2].str() + ": error: " + match[3].str();
        if (std::regex_search(line, match, mesa) && !shader.empty()) return shader + ":" + match[1].str() + ": " + match[2].str();
        if (std::regex_search(line, match, shaderFile)) shader = inSubmission(match[1], submission);
    }
    return "";
}

// The submission folder's own name: reports are read by the student, who must not see where the
// instructor keeps the class (a trailing slash is ignored).
std::string folderName(const std::string& path) {
    fs::path folder(path);
    if (!folder.has_filename()) folder = folder.parent_path();
    return folder.filename().string();
}

// The first line of `text` that says something.
std::string firstLine(const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.find_first_not_of(" \t") != std::string::npos) return line;
    return "";
}

} // namespace

std::string Report::fixFirst() const {
    if (status == Status::GraderError) return "fix first: nothing in your files; the grader itself failed (ask the instructor)";
    if (status != Status::Graded) {
        const std::string error = firstError(message, submission);
        if (!error.empty()) return "fix first: " + error;
        std::string line = firstLine(message);
        const std::string dangling = " Its last output:"; // the output follows on the next lines
        if (line.size() > dangling.size() && line.compare(line.size() - dangling.size(), dangling.size(), dangling) == 0)
            line.erase(line.size() - dangling.size());
        return "fix first: " + line;
    }
    const std::vector<int> steps = failedSteps();
    if (steps.empty()) return "";
    const Check* check = blamedBy(*this, steps.front());
    return "fix first: step " + std::to_string(steps.front()) + " - " + (check != nullptr ? check->id + ": " + check->diagnosis : "");
}

namespace {

std::string summary(const Report& report) {
    if (report.status != Status::Graded) return std::string(statusName(report.status)) + ": score 0; " + report.fixFirst();
    const std::vector<int> failed = report.failedSteps();
    if (failed.empty()) return "score " + std::to_string(report.score()) + ": every check passed";
    std::string steps;
    for (int step : failed) steps += (steps.empty() ? "" : ", ") + std::to_string(step);
    return "score " + std::to_string(report.score()) + ": steps " + steps + " lose points; " + report.fixFirst();
}

} // namespace

void writeReportJson(const Report& report, const std::string& path) {
    std::ostringstream out;
    out << "{\n  \"submission\": " << jsonQuoted(report.submission) << ",\n  \"path\": " << jsonQuoted(folderName(report.path))
        << ",\n  \"part\": " << report.part << ",\n  \"status\": " << jsonQuoted(statusName(report.status))
        << ",\n  \"score\": " << report.score() << ",\n  \"message\": " << jsonQuoted(report.message)
        << ",\n  \"seconds\": " << report.seconds << ",\n  \"rubric\": " << jsonQuoted(fs::path(rubricPath()).filename().string())
        << ",\n  \"fix_first\": " << jsonQuoted(report.fixFirst()) << ",\n  \"summary\": " << jsonQuoted(summary(report))
        << ",\n  \"failed_steps\": [" << stepList(report.failedSteps()) << "],\n  \"steps\": [";
    if (report.status == Status::Graded) {
        const std::vector<int> failed = report.failedSteps();
        bool first = true;
        for (const auto& [step, points] : report.rubric) {
            const bool lost = std::find(failed.begin(), failed.end(), step) != failed.end();
            std::string by;
            for (const Check& c : report.checks) {
                const std::vector<int> steps = failedSteps(c);
                if (std::find(steps.begin(), steps.end(), step) != steps.end()) by += (by.empty() ? "" : ", ") + jsonQuoted(c.id);
            }
            out << (first ? "" : ",") << "\n    {\"step\": " << step << ", \"points\": " << points << ", \"passed\": "
                << (lost ? "false" : "true") << ", \"failed_checks\": [" << by << "], \"link\": "
                << jsonQuoted(stepAnchor(step)) << "}";
            first = false;
        }
    }
    out << "\n  ],\n  \"isolation\": " << jsonQuoted(report.isolation)
        << ",\n  \"fill_from_reference\": " << jsonQuoted(report.fill) << ",\n  \"files\": [";
    for (std::size_t i = 0; i < report.files.size(); ++i) {
        const SubmissionFile& f = report.files[i];
        out << (i ? "," : "") << "\n    {\"name\": " << jsonQuoted(f.name) << ", \"source\": " << jsonQuoted(f.source)
            << ", \"reason\": " << jsonQuoted(f.reason) << ", \"bytes\": " << f.bytes << "}";
    }
    out << "\n  ],\n  \"checks\": [";
    for (std::size_t i = 0; i < report.checks.size(); ++i) {
        const Check& c = report.checks[i];
        out << (i ? "," : "") << "\n    {\"id\": " << jsonQuoted(c.id) << ", \"steps\": [" << stepList(c.steps)
            << "], \"passed\": " << (c.passed ? "true" : "false") << ", \"measured\": " << jsonQuoted(c.measured)
            << ", \"tolerance\": " << jsonQuoted(c.tolerance) << ", \"diagnosis\": " << jsonQuoted(c.diagnosis)
            << ", \"blames\": [" << stepList(failedSteps(c)) << "], \"mistakes\": [";
        for (std::size_t m = 0; m < c.mistakes.size(); ++m) {
            const Finding& f = c.mistakes[m];
            out << (m ? ", " : "") << "{\"id\": " << jsonQuoted(f.id) << ", \"steps\": [" << stepList(f.steps) << "]";
            if (!f.parameter.empty() && !f.value.empty()) {
                out << ", \"estimate\": {\"parameter\": " << jsonQuoted(f.parameter) << ", \"value\": " << jsonNumber(f.value)
                    << ", \"tutorial\": " << jsonNumber(f.tutorial) << "}";
            }
            out << "}";
        }
        out << "]";
        if (!c.heatMap.empty()) {
            out << ", \"images\": {\"student\": " << jsonQuoted(c.studentImage) << ", \"reference\": "
                << jsonQuoted(c.referenceImage) << ", \"heat_map\": " << jsonQuoted(c.heatMap) << "}";
        }
        out << "}";
    }
    out << "\n  ]\n}\n";
    writeOutputFile(path, out.str(), "report.json");
}

void writeReportHtml(const Report& report, const std::string& path) {
    std::ostringstream out;
    // One column that reflows down to 400 px; print keeps the colours' meaning in words and borders.
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" << htmlEscape(report.submission)
        << " - Tutorial 10 Part " << report.part << "</title>\n<style>"
        << "body{font-family:system-ui,sans-serif;line-height:1.4;margin:0 auto;padding:1em;max-width:60em;color:#111}"
        << "h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.5em}"
        << ".summary{border:2px solid #333;padding:.6em .8em;border-radius:4px;background:#f6f6f6}"
        << ".fix{font-weight:bold}.check{border:1px solid #bbb;border-left:6px solid #2a7;padding:.5em .8em;margin:.6em 0;"
        << "border-radius:4px;break-inside:avoid}.check.fail{border-left-color:#c22}"
        << ".label{font-weight:bold}.fail .label{color:#a00}.pass .label{color:#175}"
        << "dl{display:grid;grid-template-columns:max-content 1fr;gap:.2em .8em;margin:.4em 0}dt{font-weight:bold}dd{margin:0;"
        << "overflow-wrap:anywhere}.images{display:flex;flex-wrap:wrap;gap:.5em}figure{margin:0;flex:1 1 10em;max-width:16em}"
        << "figure img{width:100%;image-rendering:pixelated;border:1px solid #999}figcaption{font-size:.85em}"
        << "pre{white-space:pre-wrap;background:#eee;padding:.5em;overflow-wrap:anywhere}"
        << "ul.steps{padding-left:1.2em}a{color:#05c}table{border-collapse:collapse;display:block;overflow-x:auto}"
        << "td,th{border:1px solid #999;padding:.2em .5em;text-align:left}tr.fail td{background:#fdd}"
        << "@media (max-width:30em){dl{grid-template-columns:1fr}dt{margin-top:.3em}}"
        << "@media print{body{max-width:none;font-size:10pt}a{color:#000}.check{border-left-width:3px}"
        << "a[href^=http]::after{content:\" (\" attr(href) \")\"}}</style></head><body>\n"
        << "<h1>" << htmlEscape(report.submission) << ": Tutorial 10 Part " << report.part << "</h1>\n";
    out << "<div class=\"summary\"><p>Status: <b>" << htmlEscape(statusName(report.status)) << "</b>. Score: <b>" << report.score()
        << "</b> / 100.</p>\n";
    const std::vector<int> failed = report.failedSteps();
    if (!failed.empty()) {
        out << "<p class=\"fix\">" << htmlEscape(report.fixFirst()) << "</p>\n<p>Steps that lose points: ";
        for (std::size_t i = 0; i < failed.size(); ++i)
            out << (i ? ", " : "") << "<a href=\"" << stepAnchor(failed[i]) << "\">step " << failed[i] << "</a>";
        out << ".</p>\n";
    } else if (report.status == Status::Graded) {
        out << "<p>Every check passed.</p>\n";
    }
    out << "<p>The score is the share of the rubric's points (" << htmlEscape(fs::path(rubricPath()).filename().string()) << ") of the steps that no failed "
        << "check blames; a step loses its points once, however many checks see it. " << report.passedCount() << " of "
        << report.checks.size() << " checks passed.</p></div>\n";
    if (!report.message.empty()) out << "<pre>" << htmlEscape(report.message) << "</pre>\n";
    out << "<p>Isolation: " << htmlEscape(report.isolation) << (report.isolation == "none" ? " (run with --no-sandbox: unsafe)" : "")
        << ". Missing files taken from the reference: " << htmlEscape(report.fill) << ".</p>\n";
    if (!report.files.empty()) {
        out << "<table><tr><th>file</th><th>graded from</th><th>why</th></tr>\n";
        for (const SubmissionFile& f : report.files) {
            out << "<tr" << (f.source == "ignored" || f.source == "missing" ? " class=\"fail\"" : "") << "><td>"
                << htmlEscape(f.name) << "</td><td>" << htmlEscape(f.source) << "</td><td>" << htmlEscape(f.reason) << "</td></tr>\n";
        }
        out << "</table>\n";
    }
    // Failed checks first, in the order the chain computes them: the first is where it goes wrong.
    for (int pass = 0; pass < 2; ++pass) {
        bool heading = false;
        for (const Check& c : report.checks) {
            if (c.passed != (pass == 1)) continue;
            if (!heading) out << "<h2>" << (pass == 0 ? "Failed checks" : "Passed checks") << "</h2>\n";
            heading = true;
            out << "<div class=\"check " << (c.passed ? "pass" : "fail") << "\"><p><span class=\"label\">"
                << (c.passed ? "passed" : "FAILED") << "</span> " << htmlEscape(c.id) << " (";
            for (std::size_t i = 0; i < c.steps.size(); ++i)
                out << (i ? ", " : "") << "<a href=\"" << stepAnchor(c.steps[i]) << "\">" << c.steps[i] << "</a>";
            out << ")</p>\n<dl><dt>measured</dt><dd>" << htmlEscape(c.measured) << "</dd><dt>tolerance</dt><dd>"
                << htmlEscape(c.tolerance) << "</dd>";
            if (!c.passed) {
                out << "<dt>diagnosis</dt><dd>" << htmlEscape(c.diagnosis) << "</dd>";
                const std::vector<int> blamed = failedSteps(c);
                out << "<dt>costs</dt><dd>";
                if (blamed.empty()) out << "nothing of its own (it follows from an earlier check)";
                for (std::size_t i = 0; i < blamed.size(); ++i)
                    out << (i ? ", " : "") << "<a href=\"" << stepAnchor(blamed[i]) << "\">step " << blamed[i] << "</a>";
                out << "</dd>";
            }
            out << "</dl>\n";
            if (!c.heatMap.empty()) {
                out << "<div class=\"images\"><figure><img src=\"" << htmlEscape(c.studentImage)
                    << "\" alt=\"the submission's frame\"><figcaption>the submission</figcaption></figure><figure><img src=\""
                    << htmlEscape(c.referenceImage) << "\" alt=\"the expected frame\"><figcaption>expected</figcaption></figure>"
                    << "<figure><img src=\"" << htmlEscape(c.heatMap) << "\" alt=\"difference heat-map\"><figcaption>difference "
                    << "heat-map</figcaption></figure></div>\n";
            }
            out << "</div>\n";
        }
    }
    out << "<p>Step links point at " << htmlEscape(stepAnchor(1).substr(0, stepAnchor(1).find('#')))
        << " (T10_GRADE_TUTORIAL_URL sets the course site's page).</p>\n</body></html>\n";
    writeOutputFile(path, out.str(), "report.html");
}

void writeGradebook(const std::vector<Report>& reports, const std::string& path) {
    std::ostringstream out;
    out << "submission,part,status,score,passed,total,failed_checks,failed_steps,isolation,fill_from_reference\n";
    for (const Report& r : reports) {
        std::string failed;
        for (const Check& c : r.checks)
            if (!c.passed) failed += (failed.empty() ? "" : " ") + c.id;
        out << csvField(r.submission) << "," << r.part << "," << statusName(r.status) << "," << r.score() << ","
            << r.passedCount() << "," << r.checks.size() << "," << csvField(failed) << ","
            << csvField([&] {
                   std::string steps;
                   for (int step : r.failedSteps()) steps += (steps.empty() ? "" : " ") + std::to_string(step);
                   return steps;
               }())
            << "," << r.isolation << "," << r.fill << "\n";
    }
    writeOutputFile(path, out.str(), "the gradebook");
}

} // namespace t10::grade
