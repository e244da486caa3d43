// One line for an exception; see error_line.hpp.
#include "t10/error_line.hpp"

#include <filesystem>

namespace t10 {

std::string errorLine(const std::exception& error) {
    std::string line = error.what();
    if (const auto* fsError = dynamic_cast<const std::filesystem::filesystem_error*>(&error)) {
        // libstdc++ and libc++ write "filesystem error: OPERATION: REASON [PATH1] [PATH2]".
        std::string operation;
        const std::string prefix = "filesystem error: ";
        if (line.rfind(prefix, 0) == 0) operation = line.substr(prefix.size(), line.find(": ", prefix.size()) - prefix.size());
        std::string paths = fsError->path1().string();
        if (!fsError->path2().empty()) paths += (paths.empty() ? "" : " and ") + fsError->path2().string();
        line = (paths.empty() ? "" : paths + ": ") + fsError->code().message() + (operation.empty() ? "" : " (" + operation + ")");
    }
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    return line;
}

std::string errorLine(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        return errorLine(e);
    } catch (...) {
        return "an exception that is not a std::exception (a bug)";
    }
}

} // namespace t10
