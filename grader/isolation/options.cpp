// The graders' shared command-line reading; see options.hpp.
#include "isolation/options.hpp"

#include "t10/error.hpp"

#include <cstdlib>
#include <sstream>

namespace t10::grade {

bool Arguments::next() {
    if (next_ >= argc_) return false;
    arg_ = argv_[next_++];
    return true;
}

std::string Arguments::value() {
    if (next_ >= argc_) throw UsageError(arg_ + " needs a value");
    return argv_[next_++];
}

double Arguments::number(double low, double high, const std::string& expected) {
    const std::string text = value();
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(number >= low && number <= high)) {
        std::ostringstream message;
        message << arg_ << " " << text << ": expected ";
        if (expected.empty()) message << "a number from " << low << " to " << high;
        else message << expected;
        throw UsageError(message.str());
    }
    return number;
}

bool Arguments::isolationOption(std::string& isolation) {
    if (arg_ == "--no-sandbox") {
        isolation = "none";
        return true;
    }
    if (arg_ != "--isolation") return false;
    const std::string v = value();
    if (v != "auto" && v != "namespaces" && v != "uid") throw UsageError("--isolation " + v + ": choose auto, namespaces or uid");
    if (isolation != "none") isolation = v;
    return true;
}

} // namespace t10::grade
