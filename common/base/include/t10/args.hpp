// Command-line values every program reads the same way: sizes "WIDTHxHEIGHT" (--size,
// --resize-sequence, the bench's --sizes) and file-name extensions (--output x.png, --scene x.glb).
#pragma once
#include "t10/contract.hpp"

#include <string>
#include <utility>

namespace t10 {

// "640x360" (or "640X360") -> (640, 360). Throws t10::UsageError naming the text for anything else,
// or when a side lies outside [minimumSide, maximumSide].
std::pair<int, int> parseSize(const std::string& text, int minimumSide = contract::kMinFramebufferSide,
                              int maximumSide = contract::kMaxFramebufferSide);

// True when `name` ends in `suffix`, ignoring the case of ASCII letters (".png" matches "A.PNG").
bool hasSuffix(const std::string& name, const std::string& suffix);

} // namespace t10
