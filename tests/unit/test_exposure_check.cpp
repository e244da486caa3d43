// The black-background warning's rule (common/exposure_check.hpp) without a GL context; the
// measurement itself is checked through the programs (tests/gltf/gltf_tests.cmake).
#include "t10/exposure_check.hpp"

#include "t10_catch.hpp"

TEST_CASE("the black-background warning fires from a fifth of the frame, with the keys", "[exposure]") {
    t10::BlackShare m;
    m.key = 5.65e-06;
    m.litKey = 0.217;
    m.share = 0.19;
    CHECK_FALSE(t10::blackBackgroundWarning(m).has_value());
    m.share = 0.62;
    const auto warning = t10::blackBackgroundWarning(m);
    REQUIRE(warning.has_value());
    CHECK_THAT(*warning, Catch::StartsWith("62% of the frame is black (the background), which pulls the key down to "
                                           "Ya = 5.65e-06 (the rest of the frame alone: 0.217)"));
    CHECK_THAT(*warning, Catch::Contains("Give the scene a background"));
}
