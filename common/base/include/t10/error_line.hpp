// One line for people from any exception, for handlers that must never let one end the program (the
// graders' main()).
#pragma once
#include <exception>
#include <string>

namespace t10 {

// A std::filesystem::filesystem_error as "PATH: the system's reason (the operation)", anything else
// as its what(), line breaks made spaces.
std::string errorLine(const std::exception& error);
// The same for a caught exception (std::current_exception()), which also says what one that is no
// std::exception is.
std::string errorLine(const std::exception_ptr& error);

} // namespace t10
