// What one run of a stage is asked to do: the settings of every service, each parsed by the
// service's own options group, composed here for App. A new option goes into the group of the
// service it concerns; a new service adds its settings struct and its group here.
#pragma once
#include "t10/bench.hpp"
#include "t10/context_options.hpp"
#include "t10/outputs.hpp"
#include "t10/scene_options.hpp"
#include "t10/stage.hpp"
#include "t10/views.hpp"

#include <utility>
#include <vector>

namespace t10 {

// The frame loop's own options ("Run").
struct RunSettings {
    int frames = 0;                                  // 0: until the window closes (headless runs default to 1)
    std::vector<std::pair<int, int>> resizeSequence; // --resize-sequence, one size per frame
    bool verbose = false;
};

struct Settings {
    ContextOptions context;
    RunSettings run;
    SceneSettings scene;
    OutputSettings outputs;
    ViewSettings views;
    BenchSettings bench;
};

// Adds the "Run" group to `cli`; with `then`, --then in its help (a stage without options of its own).
void addRunOptions(CLI::App& cli, RunSettings& settings, bool then);

// Adds every service's group and the stage's own options (may be empty) to `cli`, bound to
// `settings`: the command line's options, and the list a web page offers (WebPage::options, app_web.cpp).
void addSettingsOptions(CLI::App& cli, Settings& settings, const AddOptionsHook& stageOptions = {});

// Parses argv into `settings` with addSettingsOptions' options; returns as t10::parseCommandLine
// does (-1: go on, 0: help or version, 2: bad usage).
int parseSettings(int argc, const char* const* argv, const std::string& stageName, const std::string& summary,
                  Settings& settings, const AddOptionsHook& stageOptions = {});

} // namespace t10
