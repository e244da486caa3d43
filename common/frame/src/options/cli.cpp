// Command-line parsing with CLI11: the parser's policies and the exit codes. Each service adds its
// own options group (settings.cpp lists them), so this file knows none of them.
#include "t10/cli.hpp"

#include "t10/error.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

namespace t10 {

int parseCommandLine(int argc, const char* const* argv, const std::string& programName, const std::string& summary,
                     const std::function<void(CLI::App&)>& addOptions) {
    CLI::App app(summary, programName);
    app.set_version_flag("--version", programName + " " T10_VERSION);
    app.get_formatter()->column_width(34);
    // A repeated option takes its last value, so a script can append to a fixed set of arguments.
    // Set before the groups are added: each group copies the defaults when it is made.
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    if (addOptions) addOptions(app);
    // No option of ours takes an empty value, and CLI11 2.3 (Debian 12) loops forever on an empty
    // argument followed by a dashed one (`"" -a`, found by fuzz/cli_fuzzer): refused before parsing.
    for (int i = 1; i < argc; ++i) {
        if (argv[i][0] == '\0') {
            std::cerr << programName << ": error: argument " << i << " is empty"
                      << (i > 1 ? std::string(" (after ") + argv[i - 1] + ")" : std::string())
                      << "\nRun with --help for the options.\n";
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::CallForVersion&) {
        std::cout << programName << " " << T10_VERSION << "\n";
        return 0;
    } catch (const CLI::ParseError& error) {
        std::cerr << programName << ": error: " << error.what() << "\nRun with --help for the options.\n";
        return 2;
    } catch (const UsageError& error) {
        std::cerr << programName << ": error: " << error.what() << "\nRun with --help for the options.\n";
        return 2;
    }
    return -1;
}

} // namespace t10
