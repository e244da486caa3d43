// The one place the tests meet Catch2: Debian 12 ships Catch2 2.13 (<catch2/catch.hpp>, everything in
// one header, Approx and the string matchers in namespace Catch), Debian 13 and Ubuntu 24.04 ship
// Catch2 3 (split headers, Approx and the matchers moved). Test files include this header only and
// write Approx, Catch::Contains, Catch::StartsWith and Catch::EndsWith the same way on both.
#pragma once

#if __has_include(<catch2/catch_all.hpp>)
// Catch2 3.x: Catch::Approx, Catch::Matchers::ContainsSubstring (3.0 renamed the string Contains).
#include <catch2/catch_all.hpp>

using Catch::Approx;

namespace Catch {
inline Matchers::StringContainsMatcher Contains(const std::string& text,
                                                CaseSensitive sensitivity = CaseSensitive::Yes) {
    return Matchers::ContainsSubstring(text, sensitivity);
}
using Matchers::EndsWith;
using Matchers::StartsWith;
}  // namespace Catch
#else
// Catch2 2.13: Approx is global after `using Catch::Detail::Approx` inside catch.hpp; the string
// matchers are Catch::Contains/StartsWith/EndsWith already.
#include <catch2/catch.hpp>
#endif
