// Writing the reports and the gradebook; see report.hpp. Files are written to a temporary name and
// renamed into place, so a report on disk is always complete.
#include "report.hpp"

#include "t10/error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace t10::grade {

namespace {

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (const unsigned char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (c < 0x20) {
                char buffer[8];
                std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
                out += buffer;
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    return out + "\"";
}

std::string html(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string stepList(const std::vector<int>& steps) {
    std::string out;
    for (std::size_t i = 0; i < steps.size(); ++i) out += (i ? ", " : "") + std::to_string(steps[i]);
    return out;
}

void writeAtomically(const std::string& path, const std::string& content) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throw Error(temporary + ": cannot create: " + std::strerror(errno));
        out << content;
        if (!out.flush()) throw Error(temporary + ": cannot write: " + std::strerror(errno));
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) throw Error(path + ": cannot rename into place: " + error.message());
}

} // namespace

int Report::passedCount() const {
    int passed = 0;
    for (const Check& check : checks) passed += check.passed ? 1 : 0;
    return passed;
}

int Report::score() const {
    if (status != "graded" || checks.empty()) return 0;
    return passedCount() * 100 / static_cast<int>(checks.size());
}

void writeReportJson(const Report& report, const std::string& path) {
    std::ostringstream out;
    out << "{\n  \"submission\": " << jsonString(report.submission) << ",\n  \"path\": " << jsonString(report.path)
        << ",\n  \"part\": " << report.part << ",\n  \"status\": " << jsonString(report.status)
        << ",\n  \"score\": " << report.score() << ",\n  \"message\": " << jsonString(report.message)
        << ",\n  \"seconds\": " << report.seconds << ",\n  \"isolation\": " << jsonString(report.isolation)
        << ",\n  \"fill_from_reference\": " << jsonString(report.fill) << ",\n  \"files\": [";
    for (std::size_t i = 0; i < report.files.size(); ++i) {
        const SubmissionFile& f = report.files[i];
        out << (i ? "," : "") << "\n    {\"name\": " << jsonString(f.name) << ", \"source\": " << jsonString(f.source)
            << ", \"reason\": " << jsonString(f.reason) << ", \"bytes\": " << f.bytes << "}";
    }
    out << "\n  ],\n  \"checks\": [";
    for (std::size_t i = 0; i < report.checks.size(); ++i) {
        const Check& c = report.checks[i];
        out << (i ? "," : "") << "\n    {\"id\": " << jsonString(c.id) << ", \"steps\": [" << stepList(c.steps)
            << "], \"passed\": " << (c.passed ? "true" : "false") << ", \"measured\": " << jsonString(c.measured)
            << ", \"tolerance\": " << jsonString(c.tolerance) << ", \"diagnosis\": " << jsonString(c.diagnosis);
        if (!c.heatMap.empty()) {
            out << ", \"images\": {\"student\": " << jsonString(c.studentImage) << ", \"reference\": "
                << jsonString(c.referenceImage) << ", \"heat_map\": " << jsonString(c.heatMap) << "}";
        }
        out << "}";
    }
    out << "\n  ]\n}\n";
    writeAtomically(path, out.str());
}

void writeReportHtml(const Report& report, const std::string& path) {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html(report.submission)
        << " - Tutorial 10 Part " << report.part << "</title>\n<style>body{font-family:sans-serif;margin:2em;"
        << "max-width:70em}table{border-collapse:collapse}td,th{border:1px solid #999;padding:.3em .5em;"
        << "vertical-align:top}.fail{background:#fdd}.pass{background:#dfd}img{image-rendering:pixelated;"
        << "width:256px;margin-right:.5em}pre{white-space:pre-wrap;background:#eee;padding:.5em}</style></head><body>\n"
        << "<h1>" << html(report.submission) << ": Tutorial 10 Part " << report.part << "</h1>\n<p>Status: <b>"
        << html(report.status) << "</b>. Score: <b>" << report.score() << "</b> / 100 (" << report.passedCount()
        << " of " << report.checks.size() << " checks passed; the score is the share of checks passed, rounded "
        << "down).</p>\n";
    if (!report.message.empty()) out << "<pre>" << html(report.message) << "</pre>\n";
    out << "<p>Isolation: " << html(report.isolation) << (report.isolation == "none" ? " (run with --no-sandbox: unsafe)" : "")
        << ". Missing files taken from the reference: " << html(report.fill) << ".</p>\n";
    if (!report.files.empty()) {
        out << "<table><tr><th>file</th><th>graded from</th><th>why</th></tr>\n";
        for (const SubmissionFile& f : report.files) {
            out << "<tr" << (f.source == "ignored" || f.source == "missing" ? " class=\"fail\"" : "") << "><td>"
                << html(f.name) << "</td><td>" << html(f.source) << "</td><td>" << html(f.reason) << "</td></tr>\n";
        }
        out << "</table>\n";
    }
    if (!report.checks.empty()) {
        out << "<table><tr><th>check</th><th>steps</th><th>result</th><th>measured</th><th>tolerance</th>"
            << "<th>diagnosis</th></tr>\n";
        for (const Check& c : report.checks) {
            out << "<tr class=\"" << (c.passed ? "pass" : "fail") << "\"><td>" << html(c.id) << "</td><td>"
                << stepList(c.steps) << "</td><td>" << (c.passed ? "passed" : "FAILED") << "</td><td>"
                << html(c.measured) << "</td><td>" << html(c.tolerance) << "</td><td>" << html(c.diagnosis)
                << "</td></tr>\n";
        }
        out << "</table>\n";
    }
    for (const Check& c : report.checks) {
        if (c.heatMap.empty()) continue;
        out << "<h2>" << html(c.id) << "</h2>\n<p>" << html(c.diagnosis) << "</p>\n<p><img src=\""
            << html(c.studentImage) << "\" alt=\"student frame\"><img src=\"" << html(c.referenceImage)
            << "\" alt=\"reference frame\"><img src=\"" << html(c.heatMap) << "\" alt=\"difference heat-map\"></p>"
            << "<p>Left: the submission's frame; middle: the reference; right: the difference heat-map.</p>\n";
    }
    out << "</body></html>\n";
    writeAtomically(path, out.str());
}

void writeGradebook(const std::vector<Report>& reports, const std::string& path) {
    std::ostringstream out;
    out << "submission,part,status,score,passed,total,failed_checks,isolation,fill_from_reference\n";
    for (const Report& r : reports) {
        std::string failed;
        for (const Check& c : r.checks)
            if (!c.passed) failed += (failed.empty() ? "" : " ") + c.id;
        out << csvField(r.submission) << "," << r.part << "," << r.status << "," << r.score() << ","
            << r.passedCount() << "," << r.checks.size() << "," << csvField(failed) << "," << r.isolation << ","
            << r.fill << "\n";
    }
    writeAtomically(path, out.str());
}

} // namespace t10::grade
