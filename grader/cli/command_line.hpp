// t10-grade's command line: what it asks for (Config), its usage text, and parse(), which checks every
// option and names each submission's report folder.
#pragma once
#include "intake/submission_files.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace t10::grade {

struct Config {
    int part = 0;
    std::string reportDir = "grade-report";
    int jobs = 1;
    double timeout = 60.0;
    std::string cacheDir = T10_GRADE_CACHE_DIR;
    std::string isolation = "auto"; // auto | namespaces | uid | none (--no-sandbox)
    FillPolicy fill = FillPolicy::Unchanged;
    std::vector<std::string> submissions;
    std::vector<std::string> formats;  // platform results (formats.hpp)
    std::string nameFrom;              // how a submission is named: "" (its last folder), a component index or a pattern
    std::string roster;                // a CSV mapping those names to student ids (class_index.hpp)
    std::vector<std::string> names;    // per submission: its report folder's name
    std::map<std::string, std::string> studentNames;  // per name: the student's name from the roster
    bool similarity = false;           // --similarity: the pairs to review (similarity/similarity.hpp)
    double similarityThreshold = -1;   // --similarity-threshold; < 0: the class's own
};

extern const char* const kUsage;

// The options of argv; --help prints kUsage and exits 0. Throws t10::UsageError naming the argument
// at fault: a bad option or value, a submission that is no folder, two submissions with one name, a
// roster without a submission's name, or a --report folder that would overwrite a submission; a
// folder it cannot look at throws std::filesystem::filesystem_error. Fills `config` as it goes, so
// that whoever catches knows the submissions and names read so far.
void parse(int argc, char** argv, Config& config);

} // namespace t10::grade
