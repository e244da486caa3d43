// Makes the checks of a submission's cases agree (crossCheckCases, checks.hpp): a constant the student
// wrote is the same in every render, so a finding one case makes must hold in the others.
#include "checks/checks.hpp"

#include "checks/findings.hpp"
#include "diagnosis/bloom_model.hpp"
#include "diagnosis/frame_model.hpp"
#include "t10/contract.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

namespace t10::grade {

namespace {

// A case's buffers as the frame models read them.
struct CaseFrame {
    CaseFrame(int part, const CaseRun& caseRun) : run(caseRun) {
        if (part >= 2) bloom1 = run.buffers.bloom(1);
        inputs = std::make_unique<FrameInputs>(run.buffers.accumulation, gpuMappedKey(run.buffers), part >= 2 ? &bloom1 : nullptr,
                                               nullptr, run.buffers.frameStore);
    }
    const CaseRun& run;
    ImageF bloom1;
    std::unique_ptr<FrameInputs> inputs;
};

// The checks of every case of one submission, looked up by kind ("frame" finds pot.frame, ...).
class AllCases {
public:
    AllCases(const std::vector<CaseRun>& runs, std::vector<Check>& checks) : runs_(runs), checks_(checks) {}

    const CaseRun* runOf(const Check& c) const {
        for (const CaseRun& run : runs_)
            if (c.id.rfind(run.id + ".", 0) == 0) return &run;
        return nullptr;
    }
    // The failed checks of `kind` that fail on their own (not following from an earlier one).
    std::vector<Check*> failed(const std::string& kind) const {
        std::vector<Check*> list;
        for (Check& c : checks_)
            if (!c.passed && !c.followsFrom && endsWith(c.id, "." + kind) && runOf(c) != nullptr) list.push_back(&c);
        return list;
    }

private:
    const std::vector<CaseRun>& runs_;
    std::vector<Check>& checks_;
};

// The bloom threshold: named only when one luminance interval separates the pixels in every case.
void reconcileThreshold(const AllCases& cases) {
    const std::vector<Check*> thresholds = cases.failed("bloom-threshold");
    if (std::none_of(thresholds.begin(), thresholds.end(), [&](const Check* c) { return names(*c, "bloom-threshold"); })) return;
    const ref::Rgb rec709{t10::contract::kLumaRed, t10::contract::kLumaGreen, t10::contract::kLumaBlue};
    ThresholdInterval joint;
    bool readable = true;
    for (const Check* c : thresholds) {
        const CaseRun* run = cases.runOf(*c);
        if (run->buffers.levelCount(kBloomUnit) < 1) {
            readable = false; // a case without a bloom texture allows no threshold at all
            continue;
        }
        const ThresholdInterval i = thresholdInterval(run->buffers.accumulation, run->buffers.bloom(0), rec709);
        joint.low = std::max(joint.low, i.low);
        joint.high = std::min(joint.high, i.high);
    }
    const bool consistent = readable && joint.low > 0.0 && joint.low < joint.high && joint.high < 1e300;
    for (Check* c : thresholds) {
        if (!names(*c, "bloom-threshold")) continue;
        drop(*c, "bloom-threshold");
        c->unexplained = "bloom level 0 is the first buffer that goes wrong: no one luminance threshold separates the "
                         "pixels that bloom from those that do not in every input (step 18)";
        rebuildDiagnosis(*c);
        if (c->mistakes.empty()) c->blame = {18};
        if (consistent) {
            c->diagnosis.clear();
            name(*c, "bloom-threshold", {18}, {std::sqrt(joint.low * joint.high) / ref::kYwhite},
                 "between " + format(joint.low / ref::kYwhite, 3) + " and " + format(joint.high / ref::kYwhite, 3) +
                     " x Yw over every input");
            rebuildDiagnosis(*c);
        }
    }
}

// One frame constant fitted to every case at once; the cases' own fits of it are replaced by that
// value when it explains every case within the frame's tolerance, and dropped when it does not.
void fitFrameConstantJointly(const ModelParameter& p, const std::vector<Check*>& frames,
                             const std::vector<std::unique_ptr<CaseFrame>>& cases) {
    std::vector<double> values;
    std::vector<int> steps;
    for (const Check* c : frames)
        for (const Finding& f : c->mistakes)
            if (f.id == p.id) {
                values.push_back(f.value[0]);
                steps = f.steps;
            }
    const auto model = [&p](double v) { return withSetting(p.field, v); };
    std::vector<ref::Rgb> scratch;
    const Fit rough = fitParameter(
        [&](double v) {
            double sum = 0.0;
            for (const auto& c : cases) sum += frameResidual(*c->inputs, model(v), c->run.buffers.frame, scratch, kRoughFrameStep);
            return sum;
        },
        *std::min_element(values.begin(), values.end()) * 0.5, *std::max_element(values.begin(), values.end()) * 2.0, true, 12,
        kRoughFrameFitSteps, kFrameFitStarts, kFrameResidualCeiling * double(cases.size()));
    const Fit fit = refineFrameFit(rough.value, [&](double v) {
        double sum = 0.0;
        for (const auto& c : cases) {
            const auto e = t10::test::byteError(ref::finalFrame(*c->inputs, model(v)), c->run.buffers.frame);
            sum += e.mean + e.fractionOverOne;
        }
        return sum;
    });
    bool everyCase = true;
    for (const auto& c : cases)
        everyCase = everyCase && frameWithin(t10::test::byteError(ref::finalFrame(*c->inputs, model(fit.value)), c->run.buffers.frame));
    for (Check* c : frames) {
        drop(*c, p.id);
        rebuildDiagnosis(*c);
        if (everyCase) {
            c->diagnosis.clear();
            name(*c, p.id, steps, {fit.value});
            rebuildDiagnosis(*c);
        }
    }
}

// The frame's constants: a constant the student wrote is the same in every render.
void reconcileFrameConstants(int part, const AllCases& all) {
    std::vector<Check*> frames;
    std::vector<std::unique_ptr<CaseFrame>> cases;
    std::set<std::string> named;
    for (Check* c : all.failed("frame")) {
        // A frame check exists only where the case's buffers were read (bufferChecks got that far).
        if (part >= 2 && all.runOf(*c)->buffers.levelCount(kBloomUnit) < 2) continue;
        const bool discreteOnly = !c->mistakes.empty() && std::none_of(c->mistakes.begin(), c->mistakes.end(),
                                                                          [](const Finding& f) { return f.value.size() == 1; });
        if (discreteOnly) continue;
        frames.push_back(c);
        cases.push_back(std::make_unique<CaseFrame>(part, *all.runOf(*c)));
        for (const Finding& f : c->mistakes)
            if (f.value.size() == 1 && f.id != "key-level") named.insert(f.id);
    }
    if (frames.size() < 2) return;
    for (const ModelParameter& p : kFrameParameters)
        if (named.count(p.id) != 0) fitFrameConstantJointly(p, frames, cases);
}

// The blur's constants: a case that does not pin a constant down takes the value of the cases that
// do (their median).
void reconcileBlurConstants(const AllCases& all) {
    for (const char* kind : {"blur-passes", "blur"}) {
        const std::vector<Check*> list = all.failed(kind);
        for (const ModelParameter& p : kBlurParameters) {
            std::vector<double> pinned;
            for (const Check* c : list)
                for (const Finding& f : c->mistakes)
                    if (f.id == p.id && !f.loose && f.value.size() == 1) pinned.push_back(f.value[0]);
            if (pinned.empty()) continue;
            std::sort(pinned.begin(), pinned.end());
            const double median = pinned[pinned.size() / 2];
            for (Check* c : list)
                for (Finding& f : c->mistakes)
                    if (f.id == p.id && f.loose) {
                        f.value = {median};
                        f.loose = false;
                        f.text = findingText(p.id, f.steps, f.value, "measured in the other inputs; this one does not pin it down");
                        rebuildDiagnosis(*c);
                    }
        }
    }
}

// The frame's names must explain every case: a frame check keeps a finding only when the frame
// check of every other case that fails on its own names it too (a mistake that shows as "no bloom"
// where the bloom is saturated anyway, but not elsewhere, is not that mistake). The frame is what
// every case renders whole, so a case whose frame no model explains vetoes every name. The buffer
// checks keep, of several findings, those every other case names: a case whose inputs do not pin a
// blur constant down (the extremes case's pass 1) does not veto the name the others measure.
void keepFindingsOfEveryCase(const AllCases& all) {
    const std::vector<Check*> frames = all.failed("frame");
    std::set<std::string> everywhere;
    for (const Finding& f : frames.empty() ? std::vector<Finding>{} : frames.front()->mistakes) everywhere.insert(f.id);
    for (const Check* c : frames)
        for (auto it = everywhere.begin(); it != everywhere.end();)
            it = names(*c, *it) ? std::next(it) : everywhere.erase(it);
    for (Check* c : frames) {
        const std::size_t before = c->mistakes.size();
        c->mistakes.erase(std::remove_if(c->mistakes.begin(), c->mistakes.end(),
                                         [&](const Finding& f) { return everywhere.count(f.id) == 0; }),
                          c->mistakes.end());
        if (c->mistakes.size() == before) continue;
        if (c->mistakes.empty() && c->unexplained.empty())
            c->unexplained = "no catalogue mistake explains this check in every input: compare what " + stepRange(c->steps) +
                             " write with the tutorial";
        rebuildDiagnosis(*c);
    }
    for (const char* kind : {"log-luminance", "blur-passes", "blur"}) {
        std::vector<Check*> list;
        for (Check* c : all.failed(kind))
            if (!c->mistakes.empty()) list.push_back(c);
        for (Check* c : list) {
            if (c->mistakes.size() < 2) continue;
            keepFindings(*c, [&](const Finding& f) {
                return std::all_of(list.begin(), list.end(), [&](const Check* o) { return names(*o, f.id); });
            });
        }
    }
}

} // namespace

void crossCheckCases(int part, const std::vector<CaseRun>& runs, std::vector<Check>& checks) {
    const AllCases all(runs, checks);
    reconcileThreshold(all);
    reconcileFrameConstants(part, all);
    reconcileBlurConstants(all);
    keepFindingsOfEveryCase(all);
}

} // namespace t10::grade
