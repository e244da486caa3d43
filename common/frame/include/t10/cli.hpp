// The command line every stage shares (CLI11): --help, --version, "a repeated option takes its
// last value", and bad usage as exit code 2 with a message naming the argument. The options
// themselves are registered by the services, each as its own group (settings.hpp composes them).
#pragma once
#include "t10/args.hpp"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace t10 {

// Parses argv after `addOptions` has registered the options. Returns -1 to go on, or the exit code
// to return at once: 0 after --help or --version, 2 after bad usage (the reason has been printed to
// stderr). A t10::UsageError thrown by an option group's check counts as bad usage.
int parseCommandLine(int argc, const char* const* argv, const std::string& programName, const std::string& summary,
                     const std::function<void(CLI::App&)>& addOptions);

} // namespace t10
