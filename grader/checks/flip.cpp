// FLIP's check of a scene case (flip.hpp): runs the flip-evaluator on the two frames and turns its mean
// into a Check.
#include "checks/flip.hpp"

#include "isolation/run_limited.hpp"
#include "part/part.hpp"

#include "t10/error.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace t10::grade {

namespace fs = std::filesystem;

Check flipCheck(int part, const CaseRun& run, const std::string& referenceFrame, const std::string& studentFrame,
                const std::string& reportDir, const std::vector<Check>& caseChecks) {
    Check check;
    check.id = run.id + ".flip";
    check.steps = partInfo(part).steps;
    const fs::path images = fs::path(reportDir) / "images";
    fs::create_directories(images);
    const std::string base = check.id + ".flip";
    const RunResult result = runLimited({T10_GRADE_FLIP, "-r", referenceFrame, "-t", studentFrame, "-v", "1", "-d",
                                         images.string(), "-b", base},
                                        Limits{120.0, 120, 4096}, (images / (base + ".log")).string(), "",
                                        // One OpenMP thread: on frames this small FLIP's idle threads
                                        // spinning at the end of each loop cost more than its work.
                                        {"OMP_NUM_THREADS=1"});
    const auto at = result.output.find("Mean:");
    check.tolerance = "mean FLIP <= 0.005: the reference renders identically on the same driver (0), an "
                      "equivalent rewrite measures below 1e-6, the subtlest known mistake 0.03";
    // FLIP that cannot start (its venv's interpreter missing or out of the grader's reach) is the
    // grader's failure, never the student's.
    if (!result.timedOut && result.signal == 0 && (result.exitCode == 126 || result.exitCode == 127)) {
        throw Error(std::string(T10_GRADE_FLIP) + " cannot be run (" + result.describe() + "): " + lastLines(result.output, 3) +
                    " (make grade-deps installs it; its interpreter must be reachable by the user grading)");
    }
    if (!result.ok() || at == std::string::npos) {
        // The frame passed the grader's own checks (a PNG of the case's size), so a frame FLIP still
        // cannot read is the submission's: a failed check, never the grader's failure.
        check.passed = false;
        check.measured = "FLIP cannot compare the frame with the reference (" + result.describe() + ")";
        check.diagnosis = "the frame is not a PNG that FLIP can read";
        fs::remove(images / (base + ".log"));
        return check;
    }
    const double mean = std::strtod(result.output.c_str() + at + 5, nullptr);
    // The reference program renders the same frame on the same driver bit for bit (mean 0). An
    // equivalent rewrite of the operator (the test submission "equivalent") moves a few pixels by one
    // 8-bit step and measures below 1e-6; the subtlest mistakes of the catalogue measure 0.03 (a tap
    // at 0.424 sigma, a threshold of 2.5 Yw at 160x90) and the others 0.1 to 0.75.
    constexpr double kBound = 0.005;
    check.passed = mean <= kBound;
    std::ostringstream measured;
    measured << "mean FLIP " << mean << " against the reference stage (" << run.description << ")";
    check.measured = measured.str();
    fs::remove(images / (base + ".log"));
    if (check.passed) {
        fs::remove(images / (base + ".png"));
        return check;
    }
    fs::copy_file(studentFrame, images / (check.id + ".student.png"), fs::copy_options::overwrite_existing);
    fs::copy_file(referenceFrame, images / (check.id + ".reference.png"), fs::copy_options::overwrite_existing);
    check.studentImage = "images/" + check.id + ".student.png";
    check.referenceImage = "images/" + check.id + ".reference.png";
    check.heatMap = "images/" + base + ".png";
    for (const Check& c : caseChecks) {
        if (!c.passed && !c.diagnosis.empty() && !c.followsFrom) {
            check.diagnosis += (check.diagnosis.empty() ? "" : "; ") + c.id + ": " + c.diagnosis;
        }
    }
    if (check.diagnosis.empty()) {
        check.diagnosis = "every buffer matches the CPU reference, but the frame differs from the reference stage: "
                          "look at the heat-map (for example the scene or the view, not the post-process)";
    }
    return check;
}

} // namespace t10::grade
