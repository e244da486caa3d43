// The browser's half of browser_limits.hpp (compiled instead of options/browser_limits.cpp): the
// values and options a page cannot honour, refused by name, and the bounds on one page load's frames.
#include "t10/browser_limits.hpp"

#include <array>
#include <string>
#include <utility>

namespace t10 {

namespace {

const char* const kNoFiles = "the page reads only the files packaged with it and writes none; read the frame "
                             "from the canvas instead";

// Every option a page cannot honour, by its long name, with the reason.
const std::array<std::pair<const char*, const char*>, 11> kRefused{{
    {"output", kNoFiles},
    {"exr", "the page writes no files, and OpenEXR has no WebAssembly build"},
    {"dump", kNoFiles},
    {"capture-passes", kNoFiles},
    {"scene", kNoFiles},
    {"input", kNoFiles},
    {"shader-dir", kNoFiles},
    {"keep-non-finite", "it belongs to --input, which a page has no file for"},
    {"bench", "WebGL 2 has no GPU timer queries"},
    {"bench-csv", "WebGL 2 has no GPU timer queries"},
    {"resize-sequence", "the page's size follows --size or Module.t10Set('size', ...)"},
}};

std::string withSeparators(long long value) {
    std::string text = std::to_string(value);
    for (int i = static_cast<int>(text.size()) - 3; i > 0; i -= 3) text.insert(static_cast<std::size_t>(i), ",");
    return text;
}

} // namespace

CLI::Validator refusedInBrowser(const std::string& value, const std::string& why) {
    // No description: the option's type text (which Module.t10Options reports) stays the desktop's.
    return CLI::Validator(
        [value, why](std::string& given) {
            return given == value ? value + " is not available in the web build (" + why + ")" : std::string();
        },
        "");
}

namespace browser {

std::string refusedByName(const std::vector<std::string>& args) {
    for (const std::string& arg : args) {
        if (arg.rfind("--", 0) != 0) continue;
        const std::string name = arg.substr(2, arg.find('=') == std::string::npos ? std::string::npos : arg.find('=') - 2);
        for (const auto& [refused, why] : kRefused) {
            if (name == refused) return "--" + name + " is not available in the web build (" + why + ")";
        }
    }
    return "";
}

std::string beyondBounds(const Settings& settings) {
    const long long width = settings.context.width;
    const long long height = settings.context.height;
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width > kMaxSide || height > kMaxSide || width * height > kMaxPixels) {
        return "--size " + size + ": the web build draws at most " + withSeparators(kMaxPixels) +
               " pixels a frame (3840x2160), each side at most " + std::to_string(kMaxSide) +
               ", so that a frame takes a browser without a GPU a second or two, not minutes";
    }
    const long long frames = settings.run.frames > 0 ? settings.run.frames : 1;
    if (frames * width * height > kMaxPixelFrames) {
        return "--frames " + std::to_string(frames) + ": the web build draws at most " +
               withSeparators(kMaxPixelFrames) + " pixels for the frames of one load, " +
               std::to_string(kMaxPixelFrames / (width * height)) + " frames at " + size +
               " (a few seconds in a browser without a GPU)";
    }
    return "";
}

std::string helpNote() {
    std::string names;
    for (const auto& [name, why] : kRefused) names += (names.empty() ? "--" : ", --") + std::string(name);
    return "\nIn the web build (this page) the URL's query is the command line (?size=640x360&frames=1).\n"
           "Not available here: " + names + ".\n" +
           "At most " + std::to_string(kMaxSide) + " pixels a side and " + withSeparators(kMaxPixels) +
           " a frame (3840x2160); at most " + withSeparators(kMaxPixelFrames) +
           " pixels over the frames of one load (--frames).\n";
}

} // namespace browser

} // namespace t10
