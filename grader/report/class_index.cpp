// The class index and the LMS CSV; see class_index.hpp.
#include "report/class_index.hpp"

#include "report/output.hpp"
#include "part/part.hpp"
#include "t10/error.hpp"
#include "t10/json.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace t10::grade {

namespace {

// One CSV record from `in` (RFC 4180 quoting, fields may span lines); false at the end of the file.
bool readRecord(std::istream& in, std::vector<std::string>& fields, int& line) {
    fields.clear();
    std::string field;
    bool quoted = false, any = false;
    for (char c; in.get(c);) {
        any = true;
        if (quoted) {
            if (c == '"') {
                if (in.peek() == '"') {
                    field += '"';
                    in.get();
                } else {
                    quoted = false;
                }
            } else {
                if (c == '\n') ++line;
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.push_back(field);
            field.clear();
        } else if (c == '\n') {
            ++line;
            fields.push_back(field);
            return true;
        } else if (c != '\r') {
            field += c;
        }
    }
    if (!any) return false;
    fields.push_back(field);
    return true;
}

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}


} // namespace

std::map<std::string, RosterEntry> readRoster(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("--roster " + path + ": cannot open: " + std::strerror(errno));
    std::vector<std::string> header;
    int line = 1;
    if (!readRecord(in, header, line)) throw Error("--roster " + path + ": empty (expected a header row)");
    if (!header.empty() && header[0].rfind("\xEF\xBB\xBF", 0) == 0) header[0] = header[0].substr(3); // a spreadsheet's BOM
    auto column = [&](std::initializer_list<const char*> names) {
        for (const char* name : names)
            for (std::size_t i = 0; i < header.size(); ++i)
                if (trim(header[i]) == name) return static_cast<int>(i);
        return -1;
    };
    const int key = column({"folder", "github_username"});
    const int id = column({"student_id", "identifier"});
    const int name = column({"name"});
    if (key < 0 || id < 0) {
        throw Error("--roster " + path + ": the header must name a column folder (or github_username) and a column "
                    "student_id (or identifier); it is: " + [&] {
                        std::string h;
                        for (const std::string& f : header) h += (h.empty() ? "" : ",") + f;
                        return h;
                    }());
    }
    std::map<std::string, RosterEntry> roster;
    std::set<std::string> ids;
    std::vector<std::string> fields;
    for (int record = line; readRecord(in, fields, line); record = line) {
        if (fields.size() == 1 && trim(fields[0]).empty()) continue; // a blank line
        const auto at = [&](int i) { return i >= 0 && i < static_cast<int>(fields.size()) ? trim(fields[i]) : std::string(); };
        const std::string where = "--roster " + path + ":" + std::to_string(record) + ": ";
        // GitHub Classroom's export leaves github_username empty for students who have not accepted.
        if (at(key).empty()) continue;
        if (at(id).empty()) throw Error(where + "no student id for '" + at(key) + "'");
        // The id names the student's report folder.
        if (at(id) == "." || at(id) == ".." || at(id).find_first_of("/\\") != std::string::npos)
            throw Error(where + "student id '" + at(id) + "' cannot name a folder (no / or \\, not . or ..)");
        if (!roster.emplace(at(key), RosterEntry{at(id), at(name)}).second) throw Error(where + "'" + at(key) + "' appears twice");
        if (!ids.insert(at(id)).second) throw Error(where + "student id '" + at(id) + "' appears twice");
    }
    if (roster.empty()) throw Error("--roster " + path + ": no student in it");
    return roster;
}

void writeClassIndex(const std::vector<Report>& reports, const std::map<std::string, std::string>& names,
                     const std::string& dir, const std::string& more) {
    std::vector<const Report*> sorted;
    for (const Report& r : reports) sorted.push_back(&r);
    std::sort(sorted.begin(), sorted.end(), [](const Report* a, const Report* b) { return a->submission < b->submission; });
    const int part = reports.empty() ? 0 : reports.front().part;
    auto nameOf = [&](const Report& r) {
        const auto it = names.find(r.submission);
        return it == names.end() ? std::string() : it->second;
    };

    // LMS CSV: keyed by the student id (the submission's name; the roster's id when one was given).
    std::ostringstream csv;
    csv << "student_id,name,part,score,max_score,status,report\n";
    for (const Report* r : sorted) {
        csv << csvField(r->submission) << "," << csvField(nameOf(*r)) << "," << r->part << "," << r->score() << ",100,"
            << statusName(r->status) << "," << csvField(r->submission + "/report.html") << "\n";
    }
    writeOutputFile(dir + "/grades-lms.csv", csv.str(), "the LMS CSV");

    // Scores in bins of ten; 100 alone (only a submission passing every check gets it).
    int bins[11] = {};
    double sum = 0.0;
    std::map<std::string, int> statuses;
    for (const Report* r : sorted) {
        ++bins[std::min(r->score() / 10, 10)];
        sum += r->score();
        ++statuses[statusName(r->status)];
    }
    const int most = std::max(1, *std::max_element(std::begin(bins), std::end(bins)));
    const std::vector<int> steps = partInfo(part).steps;

    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Tutorial 10 Part " << part
        << ": the class</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
        << "td,th{border:1px solid #bbb;padding:.2em .4em;text-align:center}.bar{background:#48c;height:1em;display:inline-block}"
        << ".f{background:#f99}.p{background:#cfc}.n{background:#ddd}td.l{text-align:left}</style></head><body>\n"
        << "<h1>Tutorial 10 Part " << part << ": " << sorted.size() << " submissions</h1>\n<p>Mean score "
        << (sorted.empty() ? 0.0 : sum / static_cast<double>(sorted.size())) << " / 100. Status:";
    for (const auto& [status, count] : statuses) out << " " << htmlEscape(status) << " " << count << ";";
    out << " also in <a href=\"gradebook.csv\">gradebook.csv</a> and <a href=\"grades-lms.csv\">grades-lms.csv</a>.</p>\n"
        << "<h2>Score distribution</h2>\n<table>\n";
    for (int b = 10; b >= 0; --b) {
        const std::string label = b == 10 ? "100" : std::to_string(b * 10) + "-" + std::to_string(b * 10 + 9);
        out << "<tr><td class=\"l\">" << label << "</td><td class=\"l\"><span class=\"bar\" style=\"width:"
            << bins[b] * 20 * 10 / most << "px\"></span> " << bins[b] << "</td></tr>\n";
    }
    out << "</table>\n<h2>Failed steps</h2>\n<p>A cell is red where a failed check blames the step (the "
        << "rubric's points for it are lost), green where none does, grey where the submission was not graded "
        << "(its status says why). Hover a red cell for the checks. Each name links to its report.</p>\n"
        << "<table><tr><th>submission</th><th>score</th><th>status</th>";
    for (int step : steps) out << "<th>" << step << "</th>";
    out << "</tr>\n";
    std::map<int, int> failures;
    for (const Report* r : sorted) {
        std::map<int, StepResult> byStep;
        for (StepResult& s : stepResults(r->scored())) byStep[s.step] = s;
        const std::string name = nameOf(*r);
        out << "<tr><td class=\"l\"><a href=\"" << htmlEscape(r->submission) << "/report.html\">" << htmlEscape(r->submission)
            << "</a>" << (name.empty() ? "" : " (" + htmlEscape(name) + ")") << "</td><td>" << r->score() << "</td><td>"
            << htmlEscape(statusName(r->status)) << "</td>";
        for (int step : steps) {
            const auto it = byStep.find(step);
            if (r->status != Status::Graded) {
                out << "<td class=\"n\"></td>";
            } else if (it == byStep.end()) {
                out << "<td class=\"o\"></td>";
            } else if (it->second.passed) {
                out << "<td class=\"p\"></td>";
            } else {
                std::string failed;
                for (const Check* c : it->second.checks)
                    if (!c->passed) failed += (failed.empty() ? "" : ", ") + c->id;
                ++failures[step];
                out << "<td class=\"f\" title=\"" << htmlEscape(failed) << "\">x</td>";
            }
        }
        out << "</tr>\n";
    }
    out << "<tr><th>failed by</th><th></th><th></th>";
    for (int step : steps) out << "<th>" << failures[step] << "</th>";
    out << "</tr>\n</table>\n" << more << "</body></html>\n";
    writeOutputFile(dir + "/index.html", out.str(), "the class index");
}

} // namespace t10::grade
