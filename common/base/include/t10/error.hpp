// Errors that end a run with a specific exit code: 2 for bad usage, 1 for everything else
// (missing files, shader errors, GL errors). runStage() prints them and returns the code.
#pragma once
#include <stdexcept>
#include <string>

namespace t10 {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, int exitCode = 1)
        : std::runtime_error(message), exitCode_(exitCode) {}
    int exitCode() const { return exitCode_; }

private:
    int exitCode_;
};

// Bad command-line usage: exit code 2.
class UsageError : public Error {
public:
    explicit UsageError(const std::string& message) : Error(message, 2) {}
};

} // namespace t10
