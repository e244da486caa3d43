// The context's options group on the command line: --headless, --backend and --size, parsed into
// the ContextOptions that Context::create takes.
#pragma once
#include "t10/context.hpp"

namespace CLI {
class App;
}

namespace t10 {

// Adds the "Context" group to `cli`. After parsing, `options` holds the backend, headless and the
// size (sizeGiven when --size was given); bad values end the parse with t10::UsageError.
void addContextOptions(CLI::App& cli, ContextOptions& options);

} // namespace t10
