// Copies a submission into the grader's private folder as hostile input: only regular files whose
// names the part expects, no symlinks followed, size- and count-capped; then adds the reference's
// files the instructor lets come from the reference. Lists every file with where it came from.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace t10::grade {

// Which missing files the grader takes from the reference stage (--fill-from-reference).
enum class FillPolicy {
    Unchanged, // only the files the part does not ask the student to change (the default)
    All,       // every missing file
    None,      // nothing: a missing file is missing
};
const char* fillPolicyName(FillPolicy policy);

struct SubmissionFile {
    std::string name;
    std::string source; // submission | reference | ignored | missing
    std::string reason; // for ignored and missing: why
    std::uintmax_t bytes = 0;
};

struct PartFiles {
    std::vector<std::string> expected; // every file of the stage the grader uses
    std::vector<std::string> asked;    // the ones the part's steps change
};

struct CopiedSubmission {
    std::vector<SubmissionFile> files;
    bool empty = true;                 // no file of the part came from the submission
    std::vector<std::string> missing;  // expected files neither submitted nor filled
};

constexpr std::uintmax_t kMaxSourceBytes = 256 * 1024; // far above the tutorial's largest file (~20 KiB)
constexpr int kMaxListedEntries = 64;                  // entries of a submission folder listed one by one

// Copies from `submission` into `destination` (created; must not exist) and fills from `referenceDir`.
// Throws t10::Error only for the grader's own failures (the destination cannot be written).
CopiedSubmission copySubmission(const std::string& submission, const PartFiles& part, const std::string& referenceDir,
                                FillPolicy policy, const std::string& destination);

} // namespace t10::grade
