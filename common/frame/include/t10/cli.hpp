// The command line every stage shares (CLI11). Stages with extra settings (extras/) add their own
// options through a hook; everything else is parsed and validated here.
#pragma once
#include "t10/context.hpp"
#include "t10/contract.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace t10 {

struct Options {
    bool headless = false;
    Backend backend = Backend::Auto;
    int width = 1280;
    int height = 720;
    bool sizeGiven = false;
    int frames = 0;                 // 0: until the window closes (headless runs default to 1)
    std::string output;             // --output FILE.png
    std::string exr;                // --exr FILE.exr
    std::string camera;             // --camera NAME (empty: the scene's first camera)
    std::string scene;              // --scene FILE.gltf|.glb (empty: the built-in scene)
    std::string shaderDir;          // --shader-dir DIR, searched before the stage's own folder
    std::string input;              // --input FILE.exr, replaces the scene by an HDR image
    std::string dumpDir;            // --dump DIR, textures on units 15-17 as PFM after the last frame
    std::vector<std::pair<int, int>> resizeSequence; // --resize-sequence, one size per frame
    std::string view = "final";     // --view NAME, checked against t10::findView
    bool thumbnails = false;        // --thumbnails: the strip of every target under the frame
    bool verbose = false;
    int bench = 0;        // --bench N: timed frames before the ordinary ones (0: no benchmark)
    std::string benchCsv; // --bench-csv FILE
    bool keepNonFinite = false; // --keep-non-finite: NaN and infinity of --input reach the stage as they are
};

// Adds stage-specific options to the parser (extras/); may be empty.
using AddOptionsHook = std::function<void(CLI::App&)>;

// Parses argv into `options`. Returns -1 to go on, or the exit code to return at once: 0 after
// --help or --version, 2 after bad usage (the reason has been printed to stderr).
int parseCommandLine(int argc, const char* const* argv, const std::string& stageName, const std::string& summary,
                     Options& options, const AddOptionsHook& addOptions = {});

// "640x360" -> (640, 360); throws t10::UsageError for anything else or sides outside [lo, contract::kMaxFramebufferSide].
std::pair<int, int> parseSize(const std::string& text, int minimumSide = contract::kMinFramebufferSide);

} // namespace t10
