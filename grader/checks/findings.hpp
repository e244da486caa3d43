// How a check records what it found: the catalogue's mistakes it names (findings), the steps a failure
// costs, and the diagnosis a student reads, rewritten from the findings whenever they change.
#pragma once
#include "checks/check.hpp"

#include <functional>
#include <string>
#include <vector>

namespace t10::grade {

// "step 9", "steps 6–10", "steps 19, 20, 35": steps as a diagnosis names them.
std::string stepRange(const std::vector<int>& steps);

// Names a catalogue mistake on a check: the finding, the steps it costs and the sentence a student
// reads ("your blur sigma measures 1.0; the tutorial's is 2.5 (step 27)").
std::string findingText(const std::string& id, const std::vector<int>& steps, const std::vector<double>& value,
                        const std::string& note);

// Adds the finding `id` (with its fitted `value` and a `note`) to a check that failed, charging `steps`.
void name(Check& check, const std::string& id, const std::vector<int>& steps, const std::vector<double>& value = {},
          const std::string& note = "", bool loose = false);

// Rewrites the diagnosis and the blamed steps from the findings (or the unexplained text).
void rebuildDiagnosis(Check& check);

// A failure no catalogue mistake explains (no findings, or crossCheckCases dropped them) is one
// mistake the grader cannot place among the check's steps: it costs one step, `step` (the one whose
// arithmetic makes the buffer), not all of them, so that one wrong constant nobody modelled costs less
// than steps not done (issue 38). Steps not done show as such (nothing written, or `lookMissing`: the
// steps of a "-missing" model the buffer is nearer to than to the tutorial's) and keep their cost.
void chargeOneStep(Check& check, const std::string& what, int step, const std::vector<int>& lookMissing = {});

// Keeps only the findings `keep` accepts (all of them if it accepts none) and rewrites the
// diagnosis and the blamed steps from them.
void keepFindings(Check& check, const std::function<bool(const Finding&)>& keep);

// Whether the check names the mistake `id`; drop removes it (the caller rebuilds the diagnosis).
bool names(const Check& c, const std::string& id);
void drop(Check& c, const std::string& id);

} // namespace t10::grade
