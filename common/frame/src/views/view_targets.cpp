// Finding the chain's targets from GL state; see view_targets.hpp.
#include "t10/view_targets.hpp"

#include "t10/contract.hpp"
#include "t10/readback.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace t10 {

namespace {

// The units the stage's chain uses (the fixed interface).
constexpr GLenum kAccumulationUnit = contract::kAccumulationUnit;
constexpr GLenum kLuminanceUnit = contract::kLuminanceKeyUnit;
constexpr GLenum kBloomUnit = contract::kBloomUnit;

// Framebuffer names probed for the blur target: Mesa and NVIDIA hand out small increasing
// integers, so everything from 1 to a fresh name (plus a margin for names freed out of order) is
// every framebuffer that exists.
constexpr GLuint kProbeMargin = 64;

ViewTarget levelOf(GLenum unit, GLuint texture, int level) {
    ViewTarget target;
    if (texture == 0) return target;
    glActiveTexture(GL_TEXTURE0 + unit);
    GLint immutable = GL_FALSE;
    GLint levels = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    // Texture views need immutable storage (glTexStorage2D, as every stage uses).
    if (immutable != GL_TRUE || level >= levels) return target;
    target.texture = texture;
    target.level = level;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &target.width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &target.height);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_INTERNAL_FORMAT, &target.format);
    return target;
}

// The half-resolution intermediate of the blur: a level-0 colour attachment of some framebuffer
// with the bloom's format and the size of bloom level 1, other than the bloom texture itself.
ViewTarget findBlurTarget(const ViewTarget& bloom1, GLuint bloomTexture) {
    ViewTarget found;
    if (bloom1.texture == 0) return found;
    GLint previousRead = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    GLint maxAttachments = 0;
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxAttachments);
    GLuint probe = 0;
    glGenFramebuffers(1, &probe);
    glDeleteFramebuffers(1, &probe);
    const GLuint last = probe + kProbeMargin;
    for (GLuint name = 1; name <= last && found.texture == 0; ++name) {
        if (glIsFramebuffer(name) != GL_TRUE) continue;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, name);
        for (GLint i = 0; i < std::min(maxAttachments, 8); ++i) {
            const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
            const AttachedLevel attached = attachedLevel(GL_READ_FRAMEBUFFER, attachment);
            if (attached.texture == 0 || attached.level != 0 || attached.face != 0 || attached.texture == bloomTexture)
                continue;
            glActiveTexture(GL_TEXTURE0 + views::kQueryUnit);
            glBindTexture(GL_TEXTURE_2D, attached.texture);
            ViewTarget candidate = levelOf(views::kQueryUnit, attached.texture, 0);
            glBindTexture(GL_TEXTURE_2D, 0);
            if (candidate.format == bloom1.format && candidate.width == bloom1.width &&
                candidate.height == bloom1.height) {
                found = candidate;
                break;
            }
        }
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousRead));
    return found;
}

} // namespace

ChainTargets discoverChain(int width, int height) {
    ChainTargets chain;
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    const BoundTexture accumulation = textureOnUnit(kAccumulationUnit);
    chain.accumulation = levelOf(kAccumulationUnit, accumulation.texture, 0);
    const BoundTexture luminance = textureOnUnit(kLuminanceUnit);
    chain.luminance = levelOf(kLuminanceUnit, luminance.texture, 0);
    chain.luminanceSmallest = levelOf(kLuminanceUnit, luminance.texture, std::max(luminance.levels - 1, 0));
    const GLuint bloom = textureOnUnit(kBloomUnit).texture;
    chain.bloom0 = levelOf(kBloomUnit, bloom, 0);
    chain.bloom1 = levelOf(kBloomUnit, bloom, 1);
    chain.blur = findBlurTarget(chain.bloom1, bloom);
    // A luminance texture the size of the frame is the stage's; anything else on unit 16 is not.
    if (chain.luminance.width != width || chain.luminance.height != height) {
        chain.luminance = chain.luminanceSmallest = ViewTarget{};
    }
    if (chain.bloom0.width != width || chain.bloom0.height != height) {
        chain.bloom0 = chain.bloom1 = chain.blur = ViewTarget{};
    }
    chain.luminanceMapped = chain.luminance.format != GL_R16F && chain.luminance.format != GL_R32F;
    glActiveTexture(static_cast<GLenum>(active));

    // The white point: extras/ makes it a uniform of the final program (step 37); the stages hold
    // the tutorial's literal 0.22.
    chain.ywhite = views::kYwhite;
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (program != 0) {
        const GLint location = glGetUniformLocation(static_cast<GLuint>(program), "fYwhite");
        if (location >= 0) {
            GLfloat value = 0.0f;
            glGetUniformfv(static_cast<GLuint>(program), location, &value);
            if (value > 0.0f) chain.ywhite = value;
        }
    }
    return chain;
}

std::size_t countNonFiniteTexels(const ViewTarget& target, bool rgba) {
    if (target.texture == 0) return 0;
    const ImageF image = readTextureLevel(target.texture, target.level, rgba);
    std::size_t texels = 0;
    for (std::size_t i = 0; i < image.data.size(); i += static_cast<std::size_t>(image.channels)) {
        bool bad = false;
        for (int c = 0; c < image.channels; ++c) {
            bad = bad || !std::isfinite(image.data[i + static_cast<std::size_t>(c)]);
        }
        texels += bad ? 1 : 0;
    }
    return texels;
}

std::string formatName(GLint format) {
    switch (format) {
    case GL_RGBA16F: return "GL_RGBA16F";
    case GL_R16: return "GL_R16";
    case GL_R16F: return "GL_R16F";
    case GL_R11F_G11F_B10F: return "GL_R11F_G11F_B10F";
    default: {
        char text[32];
        std::snprintf(text, sizeof text, "format 0x%04X", static_cast<unsigned>(format));
        return text;
    }
    }
}

std::string describe(const ViewTarget& target) {
    return formatName(target.format) + " level " + std::to_string(target.level) + ", " +
           std::to_string(target.width) + "x" + std::to_string(target.height);
}

} // namespace t10
