// The GL error log on a real debug context: an invalid call must be recorded with a readable
// message, or "tests fail on any GL error" would be an empty promise.
#include "gl_context.hpp"

#include "t10/context.hpp"
#include "t10/gl.hpp"
#include "t10/gl_errors.hpp"

#include "t10_catch.hpp"

#include <memory>

TEST_CASE("an invalid GL call is recorded, with the driver's message in debug builds", "[gl_errors]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    t10::GlErrorLog log;
    log.installDebugCallback();
    REQUIRE(log.empty());

    // Binding a name that glGenTextures never returned is GL_INVALID_OPERATION in a core context.
    glBindTexture(GL_TEXTURE_2D, 123456789u);
    log.pollGetError();
    REQUIRE_FALSE(log.empty());
    CHECK_THAT(log.describe(), Catch::Contains("glGetError returned 0x0502"));
#ifdef T10_GL_DEBUG
    CHECK_THAT(log.describe(), Catch::Contains("GL debug"));
#endif
    log.clear();
    glBindTexture(GL_TEXTURE_2D, 0);
    log.pollGetError();
    CHECK(log.empty());
}
