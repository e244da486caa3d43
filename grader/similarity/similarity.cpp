// Runs similarity.py over a graded class and reads its similarity.json back for the class index; see
// similarity.hpp.
#include "similarity/similarity.hpp"

#include "report/output.hpp"

#include "t10/error.hpp"
#include "t10/file.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace t10::grade {

namespace fs = std::filesystem;

namespace {

const std::string kScript = std::string(T10_GRADE_SOURCE_DIR) + "/grader/similarity/similarity.py";
const std::string kLock = std::string(T10_GRADE_SOURCE_DIR) + "/grader/similarity/jplag.lock";

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return in ? text.str() : std::string();
}

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');)
        if (!folder.empty() && access((folder + "/" + program).c_str(), X_OK) == 0) return true;
    return false;
}

// Runs argv, its output passed through; returns its exit status (-1 when it could not start or died).
int runProgram(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t child = fork();
    if (child < 0) return -1;
    if (child == 0) {
        execvp(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The index's section from similarity.json: the flagged pairs, each linked to its page.
std::string indexSection(const std::string& reportDir) {
    const nlohmann::json result = nlohmann::json::parse(fileText(reportDir + "/similarity.json"));
    std::ostringstream rows;
    int flagged = 0, rank = 0;
    for (const nlohmann::json& pair : result.at("pairs")) {
        ++rank;
        if (!pair.at("flagged").get<bool>()) continue;
        ++flagged;
        char page[32];
        std::snprintf(page, sizeof page, "similarity/pair-%04d.html", rank);
        rows << "<tr><td>" << rank << "</td><td class=\"l\">" << htmlEscape(pair.at("a").get<std::string>())
             << "</td><td class=\"l\">" << htmlEscape(pair.at("b").get<std::string>()) << "</td><td>"
             << pair.at("score").get<double>() << "</td><td>" << pair.at("matched_tokens").get<int>()
             << "</td><td>";
        if (fs::is_regular_file(reportDir + "/" + page)) rows << "<a href=\"" << page << "\">side by side</a>";
        rows << "</td></tr>\n";
    }
    std::ostringstream out;
    out << "<h2>Pairs to review</h2>\n<p>" << flagged << " pairs of students share more code beyond what the course "
        << "hands out than this class's threshold (" << htmlEscape(result.at("engine").get<std::string>()) << " "
        << htmlEscape(result.at("version").get<std::string>()) << "). Pairs to review, not a verdict: "
        << "<a href=\"similarity.html\">every pair, the thresholds and the rule</a>; also in "
        << "<a href=\"similarity.csv\">similarity.csv</a> and <a href=\"similarity.json\">similarity.json</a>.</p>\n";
    if (flagged > 0)
        out << "<table><tr><th>rank</th><th>a</th><th>b</th><th>score</th><th>shared tokens</th><th>page</th></tr>\n"
            << rows.str() << "</table>\n";
    return out.str();
}

} // namespace

std::string similarityEngineProblem() {
    const std::string engine = T10_GRADE_SIMILARITY_ENGINE;
    const std::string installed = fileText(engine + "/lock");
    if (installed.empty() || installed != fileText(kLock))
        return "JPlag is not installed in " + engine + "/ (or not the version of grader/similarity/jplag.lock): "
               "run make similarity-deps";
    if (!onPath("java")) return "Java is not installed: run make similarity-deps (Debian's default-jre-headless)";
    if (!onPath("python3")) return "python3 is not on PATH: similarity.py needs it";
    return "";
}

std::string compareClass(int part, const std::vector<std::string>& submissions, const std::vector<std::string>& names,
                         const std::string& reportDir, double threshold) {
    // Names and paths may hold any byte but NUL: handed over as NUL-separated pairs, not on a command line.
    std::string manifest;
    for (std::size_t i = 0; i < submissions.size(); ++i) manifest += names[i] + '\0' + submissions[i] + '\0';
    const std::string manifestPath = reportDir + "/.similarity-manifest";
    writeFileAtomically(manifestPath, manifest.data(), manifest.size(), "the similarity manifest");
    std::vector<std::string> args{"python3", kScript, "--part", std::to_string(part), "--report", reportDir,
                                  "--engine", T10_GRADE_SIMILARITY_ENGINE, "--manifest", manifestPath};
    if (threshold > 0) {
        args.push_back("--threshold");
        args.push_back(std::to_string(threshold));
    }
    const int status = runProgram(args);
    std::error_code ignored;
    fs::remove(manifestPath, ignored);
    if (status != 0)
        throw Error("--similarity: similarity.py " + std::string(status < 0 ? "could not run" : "exited with " +
                    std::to_string(status)) + " (its message is above); the grades are written");
    try {
        return indexSection(reportDir);
    } catch (const nlohmann::json::exception& error) {
        throw Error("--similarity: " + reportDir + "/similarity.json: " + error.what());
    }
}

} // namespace t10::grade
