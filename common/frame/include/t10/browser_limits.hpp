// What the browser build (make web) cannot honour, and how much it draws for one page load.
//
// refusedInBrowser() is a CLI11 check a stage puts on an option value the browser cannot run (extras'
// --key exact: a compute shader): in the browser build the value is refused by name when parsed, so
// it is never offered as a control (Module.t10Options leaves it out) and a URL asking for it gets the
// reason; on the desktop the check accepts everything. The rest exists in the browser build only
// (browser_limits_web.cpp): the options a page has no files or timers for, refused by name before
// parsing, and the bounds on --size and --frames, so that no query can freeze a tab.
#pragma once
#include "t10/settings.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace t10 {

// Refuses `value` with "<value> is not available in the web build (<why>)" in the browser build;
// accepts every value on the desktop.
CLI::Validator refusedInBrowser(const std::string& value, const std::string& why);

namespace browser {

// The bounds, chosen from the web stages' frame times without a GPU (Chromium drawing WebGL 2 on Mesa
// llvmpipe on two cores: Part 3 at 1280x720 about 140 ms a frame, at 1920x1080 about 400 ms, about
// 6 million pixels a second): a page load draws at most kMaxPixelFrames pixels over the frames it is
// asked for (about 3 s there, far less on a GPU), each frame at most kMaxPixels, each side at most
// kMaxSide (WebGL 2 promises textures of 2048; desktop browsers offer 8192 or 16384, phones 4096).
constexpr int kMaxSide = 4096;
constexpr long long kMaxPixels = 3840LL * 2160LL;
constexpr long long kMaxPixelFrames = 16'000'000LL;

// The first argument ("--name" or "--name=value") naming an option the page cannot honour, as the
// message refusing it; "" when there is none.
std::string refusedByName(const std::vector<std::string>& args);

// The message refusing a size or a frame count beyond the bounds above; "" when within them.
std::string beyondBounds(const Settings& settings);

// What --help adds in the browser: the options refused here and the bounds.
std::string helpNote();

} // namespace browser

} // namespace t10
