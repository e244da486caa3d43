// t10-grade's command line: its options, checked, and the names of the submissions' report folders
// (--name-from, --roster), with every fault a usage error that names the argument.
#include "cli/command_line.hpp"

#include "platforms/formats.hpp"
#include "report/class_index.hpp"
#include "isolation/options.hpp"
#include "similarity/similarity.hpp"

#include "t10/error.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <regex> // --name-from patterns only (the instructor's pattern over a path); never over student text

namespace t10::grade {

namespace fs = std::filesystem;

const char* const kUsage =
    "usage: t10-grade --part 1|2|3 [--report DIR] [--jobs N] [--timeout SECONDS] [--cache DIR] [--format F]...\n"
    "                 [--name-from N|PATTERN] [--roster CSV] [--fill-from-reference unchanged|all|none]\n"
    "                 [--isolation auto|namespaces|uid] [--no-sandbox] [--similarity [--similarity-threshold X]]\n"
    "                 SUBMISSION...\n"
    "  SUBMISSION  a folder with any of Tutorial10.cpp and the part's shaders; only regular files with the\n"
    "              part's names are taken (no symlinks, 256 KiB each); the report lists every file\n"
    "  --report    where report.json/report.html per submission and gradebook.csv go (default grade-report)\n"
    "  --jobs      submissions graded in parallel (default 1)\n"
    "  --timeout   wall-clock limit of one render, in seconds (default 60); builds get 300\n"
    "  --cache     where built submissions and the reference renders are kept (default " T10_GRADE_CACHE_DIR ")\n"
    "  --format    also write a platform's result beside each report.json: gradescope, prairielearn or classroom\n"
    "              (repeatable)\n"
    "  --name-from name each submission after a component of its path: N counts from the start (1 = the first\n"
    "              folder; -1, the default, is the last), or a regular expression whose first group (or whole\n"
    "              match) is the name, e.g. --name-from '([^/]+)/student'\n"
    "  --roster    a CSV (columns folder or github_username, student_id or identifier, optional name): names\n"
    "              each submission by the student id of its name; writes index.html and grades-lms.csv by id\n"
    "  --fill-from-reference  which missing files come from the reference stage: unchanged (default: the\n"
    "              files the part does not ask the student to change), all, or none\n"
    "  --similarity  also compare every two submissions with JPlag, the code the course hands out excluded:\n"
    "              similarity.json, .csv and .html (pairs to review, not a verdict) beside index.html, which\n"
    "              lists them; student code is only read. make similarity-deps installs JPlag and Java\n"
    "  --similarity-threshold X  flag pairs from similarity X (0-1) instead of the class's own threshold\n"
    "  --isolation how student code is contained (default auto: namespaces, else uid):\n"
    "              namespaces  bubblewrap (bwrap): no network, no environment, a fixed read-only view of the\n"
    "                          system and the project, one writable output folder, a small /tmp, killed\n"
    "                          with its pid namespace; as root it also runs as an unprivileged uid per job\n"
    "              uid         where user namespaces are not allowed (the grader must run as root): an\n"
    "                          unprivileged uid per job with the same limits; it still sees every file that\n"
    "                          is readable by others (the cache is made 0700), and the network\n"
    "  --no-sandbox  UNSAFE: runs student code as the grader's own user, with only time and size limits;\n"
    "              for trusted code on a machine with neither isolation. The report says so.\n"
    "  A submission can read only its own files, the project's public headers, libraries, shaders and\n"
    "  assets, and its run's inputs; write only its output folder and a small /tmp; it has no network\n"
    "  (namespaces), cannot outlive its run, touch other submissions or the cache, or stop the grader.\n";

namespace {

std::string submissionName(const std::string& path) {
    fs::path p = fs::path(path).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}

// The name --name-from gives the submission at `path`; throws UsageError when there is none.
std::string nameFrom(const std::string& path, const std::string& how) {
    if (how.empty()) return submissionName(path);
    std::string name;
    if (std::regex_match(how, std::regex("-?[0-9]+"))) {
        std::vector<std::string> parts;
        for (const fs::path& part : fs::path(path).lexically_normal())
            if (!part.empty() && part != "." && part != fs::path(path).root_path()) parts.push_back(part.string());
        const long index = std::strtol(how.c_str(), nullptr, 10);
        const long at = index > 0 ? index - 1 : static_cast<long>(parts.size()) + index;
        if (index == 0 || at < 0 || at >= static_cast<long>(parts.size()))
            throw UsageError("--name-from " + how + ": " + path + " has " + std::to_string(parts.size()) + " components");
        name = parts[static_cast<std::size_t>(at)];
    } else {
        std::regex pattern;
        try {
            pattern = std::regex(how);
        } catch (const std::regex_error& error) {
            throw UsageError("--name-from " + how + ": not a component index nor a valid regular expression (" + error.what() + ")");
        }
        std::smatch match;
        if (!std::regex_search(path, match, pattern)) throw UsageError("--name-from " + how + ": does not match " + path);
        name = match.size() > 1 && match[1].matched ? match[1].str() : match[0].str();
    }
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
        throw UsageError("--name-from " + how + ": gives " + path + " the name '" + name + "', which cannot name a report folder");
    return name;
}

} // namespace

void parse(int argc, char** argv, Config& config) {
    config = Config{};
    Arguments args(argc, argv);
    while (args.next()) {
        const std::string& arg = args.arg();
        if (arg == "--help" || arg == "-h") {
            std::cout << kUsage;
            std::exit(0);
        } else if (args.isolationOption(config.isolation)) {
            continue;
        } else if (arg == "--part") {
            const std::string v = args.value();
            if (v != "1" && v != "2" && v != "3") throw UsageError("--part " + v + ": choose 1, 2 or 3");
            config.part = std::stoi(v);
        } else if (arg == "--report") {
            config.reportDir = args.value();
        } else if (arg == "--jobs") {
            config.jobs = static_cast<int>(args.number(1, 64));
        } else if (arg == "--timeout") {
            config.timeout = args.number(1, 3600);
        } else if (arg == "--cache") {
            config.cacheDir = args.value();
        } else if (arg == "--format") {
            const std::string v = args.value();
            const std::vector<std::string>& known = formatNames();
            if (std::find(known.begin(), known.end(), v) == known.end())
                throw UsageError("--format " + v + ": choose gradescope, prairielearn or classroom");
            if (std::find(config.formats.begin(), config.formats.end(), v) == config.formats.end()) config.formats.push_back(v);
        } else if (arg == "--name-from") {
            config.nameFrom = args.value();
        } else if (arg == "--roster") {
            config.roster = args.value();
        } else if (arg == "--similarity") {
            config.similarity = true;
        } else if (arg == "--similarity-threshold") {
            config.similarity = true;
            config.similarityThreshold = args.number(0.01, 1);
        } else if (arg == "--fill-from-reference") {
            const std::string v = args.value();
            if (v == "unchanged") config.fill = FillPolicy::Unchanged;
            else if (v == "all") config.fill = FillPolicy::All;
            else if (v == "none") config.fill = FillPolicy::None;
            else throw UsageError("--fill-from-reference " + v + ": choose unchanged, all or none");
        } else if (arg.rfind("--", 0) == 0) {
            throw UsageError("unknown option " + arg);
        } else {
            config.submissions.push_back(arg);
        }
    }
    if (config.part == 0) throw UsageError("--part is required (1, 2 or 3)");
    if (config.submissions.empty()) throw UsageError("no SUBMISSION folder given");
    if (config.similarity) {
        const std::string problem = similarityEngineProblem();
        if (!problem.empty()) throw UsageError("--similarity: " + problem);
        if (config.submissions.size() < 2) throw UsageError("--similarity: give at least two submissions to compare");
    }
    std::map<std::string, RosterEntry> roster;
    if (!config.roster.empty()) {
        try {
            roster = readRoster(config.roster);
        } catch (const Error& error) {
            throw UsageError(error.what());
        }
    }
    // The names first, from the paths as given (no file is looked at), so that a failure below still
    // knows every submission's report folder.
    std::map<std::string, std::string> names;  // name -> the submission that has it
    for (const std::string& s : config.submissions) {
        std::string name = nameFrom(s, config.nameFrom);
        if (!config.roster.empty()) {
            const auto entry = roster.find(name);
            if (entry == roster.end()) throw UsageError(s + ": '" + name + "' is not in the roster " + config.roster);
            name = entry->second.studentId;
            if (!entry->second.name.empty()) config.studentNames[name] = entry->second.name;
        }
        if (!names.emplace(name, s).second) {
            throw UsageError("two submissions are named '" + name + "' (" + names[name] + " and " + s +
                             "): name them after another component of their path with --name-from N (1 = the first "
                             "folder, -1 = the last) or --name-from PATTERN (a regular expression whose first group is "
                             "the name), or by student id with --roster CSV");
        }
        if (config.similarity && (name == "similarity" || name.rfind("similarity.", 0) == 0))
            throw UsageError(s + ": the name '" + name + "' is a file of --similarity's report: name it otherwise (--name-from)");
        config.names.push_back(name);
    }
    const fs::path report = fs::weakly_canonical(fs::absolute(config.reportDir));
    for (std::size_t i = 0; i < config.submissions.size(); ++i) {
        const std::string& s = config.submissions[i];
        if (!fs::is_directory(s)) throw UsageError(s + ": not a folder");
        // The report folder of a submission is emptied first: it must not be, or hold, the submission.
        const fs::path folder = fs::weakly_canonical(fs::absolute(s));
        const fs::path target = report / config.names[i];
        const auto [end, unused] = std::mismatch(target.begin(), target.end(), folder.begin(), folder.end());
        if (end == target.end()) throw UsageError("--report " + config.reportDir + " would overwrite the submission " + s);
    }
}

} // namespace t10::grade
