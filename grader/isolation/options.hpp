// The command line both graders read the same way (t10-grade, t10-grade-tga): walking the
// arguments, an option's value, a number within a range, and the options that choose the
// isolation (--isolation auto|namespaces|uid, --no-sandbox). Faults throw t10::UsageError naming
// the option and its value.
#pragma once
#include <string>

namespace t10::grade {

class Arguments {
public:
    Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
    // Moves to the next argument; false after the last one.
    bool next();
    const std::string& arg() const { return arg_; }
    // The value of the current option (the argument after it): "--report needs a value" without one.
    std::string value();
    // The value as a number from low to high: "--jobs 0: expected a number from 1 to 64", or with
    // `expected` in place of "a number from 1 to 64" ("1 to 600 seconds").
    double number(double low, double high, const std::string& expected = "");
    // Reads --isolation auto|namespaces|uid or --no-sandbox into `isolation` (auto, namespaces, uid
    // or none; --no-sandbox wins in any order); false for any other argument.
    bool isolationOption(std::string& isolation);

private:
    int argc_;
    char** argv_;
    int next_ = 1;
    std::string arg_;
};

} // namespace t10::grade
