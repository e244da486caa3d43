// libFuzzer target: the command line every stage shares (parseSettings: every service's group). The input is the
// argument list, one argument per line. Parsing must end in "go on" (-1), 0 (--help, --version) or 2
// (bad usage), and "go on" must leave options that the rest of the program can trust.
#include "t10/contract.hpp"
#include "t10/settings.hpp"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

namespace {

bool sideOk(int side) { return side >= t10::contract::kMinFramebufferSide && side <= 16384; }

bool endsWithNoCase(const std::string& text, const std::string& suffix) {
    if (text.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) != suffix[i]) return false;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // Help texts and usage errors are the expected output: keep them out of the fuzzer's log.
    std::cout.rdbuf(nullptr);
    std::cerr.rdbuf(nullptr);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 4096) return 0;
    std::vector<std::string> args{"fuzz_stage"};
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            args.push_back(current);
            current.clear();
        } else {
            current += static_cast<char>(data[i]);
        }
    }
    if (!current.empty()) args.push_back(current);
    std::vector<const char*> argv;
    for (const std::string& arg : args) argv.push_back(arg.c_str());

    t10::Settings settings;
    const int code = t10::parseSettings(static_cast<int>(argv.size()), argv.data(), "fuzz_stage", "fuzz", settings);
    if (code != -1 && code != 0 && code != 2) __builtin_trap();
    if (code != -1) return 0;
    const t10::ContextOptions& context = settings.context;
    if (!sideOk(context.width) || !sideOk(context.height)) __builtin_trap();
    for (const auto& [w, h] : settings.run.resizeSequence)
        if (!(w == 0 && h == 0) && !(sideOk(w) && sideOk(h))) __builtin_trap();
    const t10::OutputSettings& outputs = settings.outputs;
    if (!outputs.output.empty() && !endsWithNoCase(outputs.output, ".png")) __builtin_trap();
    if (!outputs.exr.empty() && !endsWithNoCase(outputs.exr, ".exr")) __builtin_trap();
    if (settings.run.frames < 0 || settings.run.frames > 1000000) __builtin_trap();
    if (context.headless && context.backend == t10::Backend::Window) __builtin_trap();
    return 0;
}
