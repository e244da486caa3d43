// TexelReadback, the non-blocking read of one texel (extras' scene key): the value arrives once
// the GPU has made the copy, it is the value of the newest finished request, it never disturbs
// the pixel-pack binding that synchronous reads rely on, and a level that is not 1x1 is refused.
#include "gl_context.hpp"

#include "t10/context.hpp"
#include "t10/error.hpp"
#include "t10/gl.hpp"
#include "t10/gl_errors.hpp"
#include "t10/readback.hpp"

#include "t10_catch.hpp"

#include <memory>
#include <optional>

namespace {

// A 2x2 GL_R16F texture with a full chain whose 1x1 level holds `value`.
GLuint keyTexture(float value) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexStorage2D(GL_TEXTURE_2D, 2, GL_R16F, 2, 2);
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RED, GL_FLOAT, &value);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

} // namespace

TEST_CASE("TexelReadback returns the newest finished copy without disturbing other reads", "[readback]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    t10::GlErrorLog log;
    log.installDebugCallback();

    t10::TexelReadback readback;
    CHECK_FALSE(readback.poll().has_value()); // nothing requested yet

    const GLuint first = keyTexture(0.25f);
    const GLuint second = keyTexture(-3.5f);
    readback.request(first, 1);
    readback.request(second, 1);
    glFinish();
    const std::optional<float> value = readback.poll();
    REQUIRE(value.has_value());
    CHECK(*value == -3.5f);                   // the newer request wins (both values are exact in half float)
    CHECK_FALSE(readback.poll().has_value()); // each copy is delivered once

    GLint pack = -1;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
    CHECK(pack == 0); // a later glReadPixels into client memory still works

    CHECK_THROWS_WITH(readback.request(first, 0), "TexelReadback: level 0 is 2x2, not 1x1");
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
    CHECK(pack == 0);

    readback.destroy();
    glDeleteTextures(1, &first);
    glDeleteTextures(1, &second);
    log.pollGetError();
    CHECK(log.describe() == "");
}
