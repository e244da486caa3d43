// The page's check (Module.t10Check; the browser build only, grader/page/page.cmake): t10-grade's own
// checks, mistake catalogue and score run in a stage's page on the buffers it renders. Nothing here
// judges anything itself: the cases are t10-grade's list (capture/cases.hpp), each is rendered by the
// running page and written into its file system as a binary's --dump and --output write it
// (t10/page_capture.hpp), read by t10-grade's dump reader (checks/dump_files.hpp), checked by the
// checks' core (checks/checks.hpp: the buffer checks, then the cases reconciled), and scored by the
// one score computation with the rubric (scoring/), whose files the page packages.
//
// What the page cannot judge is listed in the answer's not_judged and scored as nothing, right or
// wrong: the cases that read an EXR input (the page has no OpenEXR), the frame against the reference
// stage's with FLIP (not compiled for the page; each case's frame check against the CPU tone map of
// its own buffers still runs), and the host code (the page runs the reference's Tutorial10.cpp: its
// answer is about the shaders alone).
#include "capture/cases.hpp"
#include "checks/checks.hpp"
#include "checks/dump_files.hpp"
#include "part/part.hpp"
#include "scoring/rubric.hpp"
#include "scoring/score.hpp"
#include "t10/error.hpp"
#include "t10/page_capture.hpp"

#include <emscripten.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace t10::grade {

namespace {

// The pictures of a failed frame are the report's (t10-grade); the page shows its own frame.
class NoImages final : public CheckImages {
public:
    void attach(Check&, const Image8&, const Image8&) override {}
};

// The part a page's stage is: the reference stage of Part N, or a student's folder named partN (as
// `make student PART=N` names it, cmake/T10WebCompare.cmake); 0 for any other stage.
int partOfStage(const std::string& stage) {
    for (int part = 1; part <= 3; ++part) {
        if (stage == partInfo(part).stage || stage == "student_part" + std::to_string(part)) return part;
    }
    return 0;
}

nlohmann::json checkJson(const Check& c) {
    nlohmann::json mistakes = nlohmann::json::array();
    for (const Finding& f : c.mistakes) {
        nlohmann::json m{{"id", f.id}, {"steps", f.steps}};
        if (!f.parameter.empty() && !f.value.empty()) {
            const auto number = [](const std::vector<double>& v) { return v.size() == 1 ? nlohmann::json(v[0]) : nlohmann::json(v); };
            m["estimate"] = {{"parameter", f.parameter}, {"value", number(f.value)}, {"tutorial", number(f.tutorial)}};
        }
        mistakes.push_back(m);
    }
    return {{"id", c.id},           {"steps", c.steps},         {"passed", c.passed},
            {"measured", c.measured}, {"tolerance", c.tolerance}, {"diagnosis", c.diagnosis},
            {"blames", failedSteps(c)}, {"mistakes", mistakes}};
}

nlohmann::json notJudged(const std::string& what, const std::string& why) { return {{"what", what}, {"why", why}}; }

// The cases of `part` the page renders, each read back as t10-grade reads a dump; the others in `skipped`.
std::vector<CaseRun> renderCases(int part, nlohmann::json& skipped) {
    std::vector<CaseRun> runs;
    for (const CaseSpec& spec : cases(part)) {
        if (!spec.camera) {
            skipped.push_back(notJudged("case " + spec.id + " (" + spec.description + ")",
                                        "it reads an EXR input image (--input), which the page cannot load (OpenEXR has "
                                        "no WebAssembly build): make check renders it"));
            continue;
        }
        const std::string dir = "/t10-check/" + spec.id;
        std::filesystem::remove_all(dir);
        capturePageCase(spec.args, dir, part == 3); // t10-grade captures the passes of Part 3 (grade.cpp)
        runs.push_back(CaseRun{spec.id, spec.description, spec.camera, loadCaseBuffers(dir)});
        // WebGL 2 clamps a channel before its 8-bit store, where native llvmpipe wraps one past 2^31 / 255
        // to 0 (reference.hpp): the frame checks model the store of the renderer that drew the frame.
        runs.back().buffers.frameStore = t10::ref::Unorm8Store::Clamped;
        skipped.push_back(notJudged(spec.id + ".flip",
                                    "the frame against the reference stage's with FLIP is not in the page; " + spec.id +
                                        ".frame checks the frame against the CPU tone map of the page's own buffers"));
    }
    return runs;
}

nlohmann::json check() {
    const auto start = std::chrono::steady_clock::now();
    const std::string stage = pageStageName();
    const int part = partOfStage(stage);
    if (part == 0) {
        return {{"error", (stage.empty() ? std::string("no stage is running") : stage) +
                              ": the grader checks Parts 1-3 (their reference stages and students' partN folders)"}};
    }
    nlohmann::json skipped = nlohmann::json::array();
    skipped.push_back(notJudged("host code (Tutorial10.cpp)", "the page runs the reference's host code: this check is "
                                                              "about the shaders alone; make check builds and checks yours"));
    const std::vector<CaseRun> runs = renderCases(part, skipped);
    NoImages images;
    std::vector<Check> checks;
    for (const CaseRun& run : runs) {
        const std::vector<Check> found = caseBufferChecks(part, run, images);
        checks.insert(checks.end(), found.begin(), found.end());
    }
    crossCheckCases(part, runs, checks);
    const Rubric rubric = loadRubric(part);
    const Scored scored{part, rubric, true, checks};
    nlohmann::json steps = nlohmann::json::array();
    for (const StepResult& s : stepResults(scored)) {
        nlohmann::json failedBy = nlohmann::json::array();
        for (const Check* c : s.checks)
            if (!c->passed) failedBy.push_back(c->id);
        steps.push_back({{"step", s.step}, {"points", s.points}, {"max_points", s.maxPoints}, {"passed", s.passed},
                         {"failed_checks", failedBy}});
    }
    nlohmann::json list = nlohmann::json::array();
    for (const Check& c : checks) list.push_back(checkJson(c));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {{"stage", stage},          {"part", part},       {"score", score(scored)},
            {"failed_steps", blamedSteps(checks)}, {"steps", steps}, {"checks", list},
            {"not_judged", skipped},   {"seconds", seconds}};
}

std::string& result() {
    static std::string text;
    return text;
}

} // namespace

} // namespace t10::grade

// The page's entry point (workbench.js wraps it as Module.t10Check): the report as JSON, or {error}.
extern "C" EMSCRIPTEN_KEEPALIVE const char* t10_check() {
    using namespace t10::grade;
    try {
        result() = check().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    } catch (const std::exception& error) {
        result() = nlohmann::json{{"error", std::string("the check could not run: ") + error.what()}}.dump(
            -1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    return result().c_str();
}
