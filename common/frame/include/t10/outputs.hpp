// The files a run writes after its last frame: --output (the default framebuffer as PNG), --exr
// (the HDR accumulation texture) and --dump (every level of the post-process textures on the
// units of contract.hpp, as PFM); --capture-passes (each blur pass as it is drawn, written during the
// frames by the pass capture of frame_observer.hpp). The service owns its options group ("Outputs").
#pragma once
#include "t10/scene.hpp"

#include <string>

namespace CLI {
class App;
}

namespace t10 {

struct OutputSettings {
    std::string output;  // --output FILE.png
    std::string exr;     // --exr FILE.exr
    std::string dumpDir; // --dump DIR, textures on units 15-17 as PFM after the last frame
    std::string capturePassesDir; // --capture-passes DIR, each blur pass of every frame (t10-grade)
};

// Adds the "Outputs" group to `cli`; bad values end the parse with t10::UsageError.
void addOutputOptions(CLI::App& cli, OutputSettings& settings);

// Writes every output `settings` asks for; throws t10::Error naming the file on failure, or when
// the last frame was 0x0.
void writeOutputs(const OutputSettings& settings, int width, int height, const Scene& scene);

// True when `settings` asks for any output file.
bool wantsOutputs(const OutputSettings& settings);

// The name --dump gives one level of the texture on a unit: "unit16_level3.pfm".
std::string dumpFileName(unsigned unit, int level);

} // namespace t10
