// The run's options and the composition of every service's group; see settings.hpp.
#include "t10/settings.hpp"

#include "t10/args.hpp"
#include "t10/cli.hpp"
#include "t10/cli_range.hpp"
#include "t10/contract.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace t10 {

void addRunOptions(CLI::App& cli, RunSettings& settings, [[maybe_unused]] bool then) {
    auto sequence = std::make_shared<std::string>(); // the text, owned by the group's callback
    CLI::Option_group* group = cli.add_option_group("Run", "How many frames, at which sizes");
    group->add_option("--frames", settings.frames,
                      "Render N frames, then exit (headless default 1; window: until closed)")
        ->check(CLI::Range(1, 1000000));
    CLI::Option* resize = group->add_option(
        "--resize-sequence", *sequence,
        "Resize before each frame: WxH,WxH,... (for tests); each size follows the --size rule, and 0x0 stands for a "
        "minimised window (nothing is rendered, so a run whose last frame is 0x0 cannot write its outputs)");
    group->add_flag("--verbose,-v", settings.verbose, "Print the GL vendor, renderer and version, and frame times");
#ifndef __EMSCRIPTEN__
    // Split off by runStage before parsing (app.hpp): here for --help only.
    if (then)
        group->add_flag(contract::kThenOption,
                        "End this run's options: the options after it are another headless run in the same process "
                        "and context, started after this run's outputs are written (t10-grade renders a submission's "
                        "cases this way)");
#endif
    group->callback([&settings, sequence, resize] {
        refuseEmpty({resize});
        if (!sequence->empty())
            settings.resizeSequence = parseResizeSequence(*sequence, [](const std::string& item) { return parseSize(item); });
    });
}

void addSettingsOptions(CLI::App& cli, Settings& settings, const AddOptionsHook& stageOptions) {
    addContextOptions(cli, settings.context);
    addRunOptions(cli, settings.run, !stageOptions); // runStage refuses --then where a stage has options
    addSceneOptions(cli, settings.scene);
    addOutputOptions(cli, settings.outputs);
    addViewOptions(cli, settings.views);
    addBenchOptions(cli, settings.bench);
    if (stageOptions) stageOptions(cli);
}

int parseSettings(int argc, const char* const* argv, const std::string& stageName, const std::string& summary,
                  Settings& settings, const AddOptionsHook& stageOptions) {
    return parseCommandLine(argc, argv, stageName, summary,
                            [&](CLI::App& cli) { addSettingsOptions(cli, settings, stageOptions); });
}

} // namespace t10
