// The buffers one rendered case wrote, in memory, as the checks read them: the accumulation texture,
// the final frame, every level of the luminance and bloom textures and the blur passes
// --capture-passes recorded. The grader fills them from a dump folder (dump_files.hpp); a page could
// fill them from its own readback.
#pragma once
#include "t10/contract.hpp"
#include "t10/image.hpp"
#include "reference.hpp"

#include <exception>
#include <map>
#include <string>
#include <vector>

namespace t10::grade {

using t10::Image8;
using t10::ImageF;

constexpr int kLuminanceUnit = static_cast<int>(t10::contract::kLuminanceKeyUnit);
constexpr int kBloomUnit = static_cast<int>(t10::contract::kBloomUnit);

// A texture level as it was read: its image, or the error reading it raised, raised again when a check
// reads the level (a level no check reads costs a submission nothing, as when the checks read files).
struct BufferLevel {
    ImageF image;
    std::exception_ptr fault;
};

// One blur pass: the subroutine it ran with and the texture level it drew into.
struct CapturedPass {
    std::string subroutine;
    ImageF image;
};

struct CaseBuffers {
    std::string name;                               // names the buffers in errors (the dump folder)
    ImageF accumulation;                            // the accumulation unit (15), level 0 (RGB)
    Image8 frame;                                   // the final frame
    // How the renderer that drew the frame stores 8 bits: llvmpipe's for t10-grade's renders; the
    // page's check (grader/page/) renders through WebGL 2, which clamps (reference.hpp).
    t10::ref::Unorm8Store frameStore = t10::ref::Unorm8Store::Llvmpipe;
    std::map<int, std::vector<BufferLevel>> units;  // every level written of each other unit (16, 17)
    bool captured = false;                          // whether the passes were recorded at all
    std::vector<CapturedPass> passes;
    std::exception_ptr passesFault;                 // raised when the checks read the passes

    // Number of levels written for `unit`.
    int levelCount(int unit) const;
    // Level `level` of the texture on `unit`; throws t10::Error if the stage did not write it (named as
    // the stage's --dump names its file), or the error reading it raised.
    ImageF level(int unit, int level) const;
    ImageF bloom(int level) const { return this->level(kBloomUnit, level); }
    int luminanceLevels() const { return levelCount(kLuminanceUnit); }
};

// The value the final pass reads with its huge bias: the average of the smallest luminance level
// written; throws t10::Error when there is none.
double gpuMappedKey(const CaseBuffers& buffers);

// One rendered case: what the stage wrote with --dump and --output.
struct CaseRun {
    std::string id;          // pot, npot, extremes, hot
    std::string description; // "128x128, camera default"
    bool camera = false;     // a scene render (FLIP is compared against the reference stage)
    CaseBuffers buffers;
};

} // namespace t10::grade
