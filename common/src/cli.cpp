// Command-line parsing with CLI11: every option, its help text, and the checks that turn bad usage
// into exit code 2 with a message naming the argument.
#include "t10/cli.hpp"

#include "t10/bench.hpp"
#include "t10/cli_range.hpp"

#include "t10/error.hpp"
#include "t10/views.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

namespace t10 {

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    if (text.size() < suffix.size()) return false;
    std::string tail = text.substr(text.size() - suffix.size());
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == suffix;
}

} // namespace

std::pair<int, int> parseSize(const std::string& text, int minimumSide) {
    const auto x = text.find_first_of("xX");
    auto side = [&](const std::string& part) {
        if (part.empty() || part.size() > 6 || part.find_first_not_of("0123456789") != std::string::npos) {
            throw UsageError("size '" + text + "' is not WIDTHxHEIGHT (for example 1280x720)");
        }
        const int value = std::stoi(part);
        if (value < minimumSide || value > contract::kMaxFramebufferSide) {
            throw UsageError("size '" + text + "': each side must be from " + std::to_string(minimumSide) + " to " +
                             std::to_string(contract::kMaxFramebufferSide));
        }
        return value;
    };
    if (x == std::string::npos) throw UsageError("size '" + text + "' is not WIDTHxHEIGHT (for example 1280x720)");
    return {side(text.substr(0, x)), side(text.substr(x + 1))};
}

int parseCommandLine(int argc, const char* const* argv, const std::string& stageName, const std::string& summary,
                     Options& options, const AddOptionsHook& addOptions) {
    CLI::App app(summary, stageName);
    app.set_version_flag("--version", stageName + " " T10_VERSION);
    app.get_formatter()->column_width(34);
    // A repeated option takes its last value, so a script can append to a fixed set of arguments.
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

    std::string backend = "auto";
    std::string size;
    std::string resizeSequence;
    app.add_flag("--headless", options.headless, "Render without a window (the default when there is no display)");
    app.add_option("--backend", backend, "auto | window | egl | osmesa (auto: a window when there is a display, "
                                         "else EGL, else OSMesa)")
        ->check(CLI::IsMember({"auto", "window", "egl", "osmesa"}));
    CLI::Option* sizeOption = app.add_option("--size", size, "Framebuffer size WIDTHxHEIGHT, each side 2 to 16384 "
                                                              "(default 1280x720); --input images follow the same rule");
    app.add_option("--frames", options.frames, "Render N frames, then exit (headless default 1; window: until closed)")
        ->check(CLI::Range(1, 1000000));
    CLI::Option* outputOption = app.add_option("--output", options.output, "Write the final frame as an 8-bit PNG (exactly what the window shows)");
    CLI::Option* exrOption = app.add_option("--exr", options.exr, "Write the HDR accumulation buffer as an OpenEXR file (RGBA half)");
    app.add_option("--camera", options.camera, "A camera of the scene (built-in: default, floor, lights, crates; "
                                               "any scene: framing; default: the scene's first)");
    app.add_option("--scene", options.scene, "Render this glTF 2.0 file (.gltf or .glb) instead of the built-in scene");
    app.add_option("--shader-dir", options.shaderDir, "Look for shaders in DIR before the stage's own folder")
        ->check(CLI::ExistingDirectory);
    app.add_option("--input", options.input, "Post-process this HDR image (OpenEXR) instead of rendering the scene")
        ->check(CLI::ExistingFile);
    CLI::Option* dumpOption = app.add_option("--dump", options.dumpDir, "After the last frame, write every level of the textures on units "
                                              "15-17 (contract.hpp) as PFM files into DIR (for numeric checks)");
    CLI::Option* resizeOption = app.add_option(
        "--resize-sequence", resizeSequence,
        "Resize before each frame: WxH,WxH,... (for tests); each size follows the --size rule, and 0x0 stands for a "
        "minimised window (nothing is rendered, so a run whose last frame is 0x0 cannot write its outputs)");
    app.add_flag("--keep-non-finite", options.keepNonFinite,
                 "Pass NaN and infinite pixels of --input on unchanged (default: +infinity becomes the largest half "
                 "float, 65504, NaN and -infinity 0, with a warning; for testing a stage's own handling)");
    app.add_option("--view", options.view, "What to show: " + allViewNames() + " (default final; V cycles in a window)");
    app.add_flag("--thumbnails", options.thumbnails, "Draw a strip of thumbnails of every target of the chain "
                                                      "along the bottom, each labelled (T toggles in a window)");
    app.add_flag("--verbose,-v", options.verbose, "Print the GL vendor, renderer and version, and frame times");
    CLI::Option* bench = app.add_option("--bench", options.bench,
                                        "Render N frames after " + std::to_string(kBenchWarmUpFrames) +
                                            " warm-up frames and print the median time of the frame and of each pass "
                                            "the stage times (use with --headless)")
                             ->check(inRange(1, 100000, true));
    app.add_option("--bench-csv", options.benchCsv, "Also write the --bench table as CSV "
                                                    "(pass,median_ms,min_ms,max_ms,frames)")
        ->needs(bench);
    if (addOptions) addOptions(app);

    try {
        app.parse(argc, argv);
        options.backend = backend == "window" ? Backend::Window
                        : backend == "egl"    ? Backend::Egl
                        : backend == "osmesa" ? Backend::OsMesa
                                              : Backend::Auto;
        if (options.headless && options.backend == Backend::Window) {
            throw UsageError("--headless contradicts --backend window");
        }
        // An empty value is refused rather than read as "not given".
        for (const CLI::Option* option : {sizeOption, outputOption, exrOption, dumpOption, resizeOption}) {
            if (option->count() > 0 && option->as<std::string>().empty())
                throw UsageError(option->get_name() + ": the value is empty");
        }
        if (sizeOption->count() > 0) {
            std::tie(options.width, options.height) = parseSize(size);
            options.sizeGiven = true;
        }
        if (!options.output.empty() && !endsWith(options.output, ".png")) {
            throw UsageError("--output " + options.output + ": the file name must end in .png");
        }
        if (!options.exr.empty() && !endsWith(options.exr, ".exr")) {
            throw UsageError("--exr " + options.exr + ": the file name must end in .exr");
        }
        if (!options.scene.empty() && !endsWith(options.scene, ".gltf") && !endsWith(options.scene, ".glb")) {
            throw UsageError("--scene " + options.scene + ": the file name must end in .gltf or .glb");
        }
        if (!findView(options.view)) {
            throw UsageError("--view " + options.view + ": unknown view (choose from " + allViewNames() + ")");
        }
        if (!resizeSequence.empty())
            options.resizeSequence = parseResizeSequence(resizeSequence, [](const std::string& item) { return parseSize(item); });
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::CallForVersion&) {
        std::cout << stageName << " " << T10_VERSION << "\n";
        return 0;
    } catch (const CLI::ParseError& error) {
        std::cerr << stageName << ": error: " << error.what() << "\nRun with --help for the options.\n";
        return 2;
    } catch (const UsageError& error) {
        std::cerr << stageName << ": error: " << error.what() << "\nRun with --help for the options.\n";
        return 2;
    }
    return -1;
}

} // namespace t10
