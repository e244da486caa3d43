// The files a run writes after its last frame: --output (the default framebuffer as PNG), --exr
// (the HDR accumulation texture) and --dump (every level of the post-process textures on the
// units of contract.hpp, as PFM).
#pragma once
#include "t10/cli.hpp"
#include "t10/scene.hpp"

namespace t10 {

// Writes every output `options` asks for; throws t10::Error naming the file on failure, or when
// the last frame was 0x0.
void writeOutputs(const Options& options, int width, int height, const Scene& scene);

// True when `options` asks for any output file.
bool wantsOutputs(const Options& options);

// The name --dump gives one level of the texture on a unit: "unit16_level3.pfm".
std::string dumpFileName(unsigned unit, int level);

} // namespace t10
