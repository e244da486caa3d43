// TexelReadback, the non-blocking read of one texel (extras' scene key): the value arrives once
// the GPU has made the copy, it is the value of the newest finished request, it never disturbs
// the pixel-pack binding that synchronous reads rely on, and a level that is not 1x1 is refused; and the
// two queries the views and checks share (what a texture unit and a colour attachment hold).
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

TEST_CASE("textureOnUnit and attachedLevel say what a unit and an attachment hold", "[readback]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    t10::GlErrorLog log;
    log.installDebugCallback();

    const GLuint key = keyTexture(1.0f);
    glActiveTexture(GL_TEXTURE0 + 5);
    glBindTexture(GL_TEXTURE_2D, key);
    glActiveTexture(GL_TEXTURE0 + 2);
    const t10::BoundTexture bound = t10::textureOnUnit(5);
    CHECK(bound.texture == key);
    CHECK(bound.format == GL_R16F);
    CHECK(bound.levels == 2);
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    CHECK(active == GL_TEXTURE0 + 2); // put back
    CHECK(t10::textureOnUnit(6).texture == 0);

    // Level 1 of the key texture on attachment 1, a renderbuffer on attachment 0.
    GLuint framebuffer = 0;
    GLuint renderbuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glGenRenderbuffers(1, &renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 2, 2);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, key, 1);
    const t10::AttachedLevel attached = t10::attachedLevel(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1);
    CHECK(attached.texture == key);
    CHECK(attached.level == 1);
    CHECK(attached.face == 0);
    CHECK(t10::attachedLevel(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0).texture == 0); // a renderbuffer
    CHECK(t10::attachedLevel(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT2).texture == 0); // nothing

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &renderbuffer);
    glActiveTexture(GL_TEXTURE0 + 5);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &key);
    log.pollGetError();
    CHECK(log.describe() == "");
}
