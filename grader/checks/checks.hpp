// The checks t10-grade runs on one rendered case of a submission: every intermediate buffer that
// the part writes (luminance levels and key, bloom levels, each blur pass as --capture-passes
// recorded it, the blurred bloom) against the CPU reference (common/reference), and the final frame
// against the CPU tone map of the buffers the GPU produced. The buffer checks are one table
// (table.cpp, checkTable: id, steps, the checks each follows from, its function). A failed check fits
// the tutorial's constants to the buffers (diagnosis/) and names a mistake of the catalogue
// (catalogue.hpp) only when its fitted model explains them within the check's tolerance, in every case
// (crossCheckCases, reconcile.cpp); otherwise it says how the buffer is wrong.
//
// The checks read a case's buffers from memory (buffers.hpp) and hand the images of a failed frame to
// the caller (CheckImages): no file system, process or FLIP call, so that a page can run them on its
// own readback. The grader loads a dump folder into buffers (dump_files.hpp), writes the images into
// the report (report/check_images.hpp) and compares the frame with FLIP (flip.hpp).
#pragma once
#include "checks/buffers.hpp"
#include "checks/check.hpp"

#include <vector>

namespace t10::grade {

// Where the pictures of a failed frame check go: the submission's frame beside the expected one. The
// writer sets the check's image fields (studentImage, referenceImage, heatMap).
class CheckImages {
public:
    virtual ~CheckImages() = default;
    virtual void attach(Check& check, const Image8& student, const Image8& expected) = 0;
};

// The buffer checks of `part` (1, 2 or 3) for one case; throws t10::Error naming a buffer the part
// must write that is missing or unreadable.
std::vector<Check> bufferChecks(int part, const CaseRun& run, CheckImages& images);

// bufferChecks, with a buffer the part must write that is missing or malformed reported as one failed
// check, "<case>.buffers", saying which (costing every step of the part) instead of thrown: what
// t10-grade and the page's check (grader/page/) run on each case.
std::vector<Check> caseBufferChecks(int part, const CaseRun& run, CheckImages& images);

// Makes the cases agree: a constant the student wrote is the same in every render, so the frame's
// constants are fitted once to every case whose frame failed (kept only when one value explains
// them all), the bloom threshold is the one luminance interval every case allows, and of several
// mistakes that explain one case only those the other cases' same check also names are kept.
// Rewrites the diagnoses and blamed steps of the checks it changes.
void crossCheckCases(int part, const std::vector<CaseRun>& runs, std::vector<Check>& checks);

} // namespace t10::grade
