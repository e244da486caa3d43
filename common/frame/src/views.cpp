// The view selector (see views.hpp): finds the chain's targets from what the stage left bound,
// samples each through a texture view of the level it shows, and draws one full-screen pass over
// framebuffer 0 with common/shaders/views/View.frag.
#include "t10/views.hpp"

#include "t10/error.hpp"
#include "t10/quad.hpp"
#include "t10/readback.hpp"
#include "t10/scene_key.hpp"
#include "t10/shader.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace t10 {

namespace {

constexpr std::array<const char*, kViewCount> kNames = {"final",  "hdr",  "luminance", "key", "bloom0",
                                                        "bloom1", "blur", "ev",        "nan"};

// The units the stage's chain uses (the fixed interface) and the ones the view pass samples from:
// texture views of single levels, on units no stage touches.
constexpr GLenum kAccumulationUnit = contract::kAccumulationUnit;
constexpr GLenum kLuminanceUnit = contract::kLuminanceKeyUnit;
constexpr GLenum kBloomUnit = contract::kBloomUnit;
constexpr GLuint kFirstViewUnit = 18; // accumulation, luminance, bloom0, bloom1, blur
constexpr int kSampledTargets = 5;
constexpr GLuint kQueryUnit = kFirstViewUnit + kSampledTargets; // where a found texture is inspected

// Framebuffer names probed for the blur target: Mesa and NVIDIA hand out small increasing
// integers, so everything from 1 to a fresh name (plus a margin for names freed out of order) is
// every framebuffer that exists.
constexpr GLuint kProbeMargin = 64;

// View.frag's uniform locations.
enum Location : GLint {
    kMode = 0,
    kSize = 1,
    kExposure = 2,
    kKeyPosition = 3,
    kKey = 4,
    kDg = 5,
    kYwhite = 6,
    kMapped = 7,
    kLegend = 8,
    kPresent = 9,
    kScale = 10, // kScaleStops vec3s
    kOrigin = 17,
    kTextScale = 18,
    kText = 19 // kLabelChars ints
};

// Thumbnail labels: glyph indices into View.frag's 3x5 font, which holds exactly these characters.
constexpr const char* kGlyphChars = "0123456789xRGBAF_ ";
constexpr int kGlyphRows = 5;
constexpr int kLabelScale = 2;
constexpr int kLabelChars = 24;

GLint glyphIndex(char c) {
    const char* found = std::strchr(kGlyphChars, c);
    return found != nullptr && c != '\0' ? static_cast<GLint>(found - kGlyphChars) : -1;
}

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

GLuint boundTexture(GLenum unit, GLint& levels) {
    glActiveTexture(GL_TEXTURE0 + unit);
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    levels = 0;
    if (texture != 0) glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    return static_cast<GLuint>(texture);
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
            GLint type = GL_NONE;
            glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
            if (type != GL_TEXTURE) continue;
            GLint texture = 0;
            GLint level = 0;
            GLint face = 0;
            glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
            glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                                  GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
            glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                                  GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &face);
            if (level != 0 || face != 0 || static_cast<GLuint>(texture) == bloomTexture) continue;
            glActiveTexture(GL_TEXTURE0 + kQueryUnit);
            glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
            ViewTarget candidate = levelOf(kQueryUnit, static_cast<GLuint>(texture), 0);
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

// A single-level texture view of `target`, bound to `unit` with nearest filtering.
GLuint bindLevelView(GLuint unit, const ViewTarget& target) {
    glActiveTexture(GL_TEXTURE0 + unit);
    if (target.texture == 0) {
        glBindTexture(GL_TEXTURE_2D, 0);
        return 0;
    }
    GLuint view = 0;
    glGenTextures(1, &view);
    glTextureView(view, GL_TEXTURE_2D, target.texture, static_cast<GLenum>(target.format),
                  static_cast<GLuint>(target.level), 1, 0, 1);
    glBindTexture(GL_TEXTURE_2D, view);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return view;
}

std::size_t countNonFiniteTexels(const ViewTarget& target, bool rgba) {
    if (target.texture == 0) return 0;
    const ImageF image = readTextureLevel(target.texture, target.level, rgba);
    std::size_t texels = 0;
    for (std::size_t i = 0; i < image.data.size(); i += static_cast<std::size_t>(image.channels)) {
        bool bad = false;
        for (int c = 0; c < image.channels; ++c) bad = bad || !std::isfinite(image.data[i + static_cast<std::size_t>(c)]);
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

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.5g", value);
    return text;
}

} // namespace

const char* viewName(View view) { return kNames[static_cast<std::size_t>(view)]; }

std::optional<View> findView(const std::string& name) {
    for (int i = 0; i < kViewCount; ++i) {
        if (name == kNames[static_cast<std::size_t>(i)]) return static_cast<View>(i);
    }
    return std::nullopt;
}

std::string allViewNames() {
    std::string names;
    for (const char* name : kNames) names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

namespace views {

double displayEncode(double linear, double exposure) {
    return std::pow(std::clamp(linear * exposure, 0.0, 1.0), 1.0 / kDisplayGamma);
}

const std::array<Rgb, kScaleStops>& colourScaleStops() {
    static const std::array<Rgb, kScaleStops> stops = {{{0.0, 0.0, 0.25},
                                                        {0.0, 0.0, 1.0},
                                                        {0.0, 1.0, 1.0},
                                                        {0.0, 1.0, 0.0},
                                                        {1.0, 1.0, 0.0},
                                                        {1.0, 0.0, 0.0},
                                                        {1.0, 1.0, 1.0}}};
    return stops;
}

Rgb colourScale(double t) {
    const auto& stops = colourScaleStops();
    const double x = std::clamp(t, 0.0, 1.0) * (kScaleStops - 1);
    const int i = std::min(static_cast<int>(x), kScaleStops - 2);
    const double f = x - i;
    Rgb colour{};
    for (int c = 0; c < 3; ++c) colour[c] = stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f;
    return colour;
}

double rangeMap(double y, double ywhite) {
    return (std::log(y + kEpsilon) - std::log(kEpsilon)) / (std::log(ywhite) - std::log(kEpsilon));
}

double keyFromMapped(double mapped, double ywhite) {
    return std::exp(mapped * (std::log(ywhite) - std::log(kEpsilon)) + std::log(kEpsilon));
}

double middleGrey(double key) { return 1.03 - 2.0 / (2.0 + std::log10(key + 1.0)); }

EvClass classifyEv(double y, double key, double ywhite) {
    const double yr = middleGrey(key) / key * y;
    if (yr >= ywhite) return {EvKind::Burnt, kEvHighest};
    const double displayed = yr * (1.0 + yr / (ywhite * ywhite)) / (1.0 + yr);
    if (!(displayed >= 0.5 / 255.0)) return {EvKind::Black, kEvLowest};
    const int stop = std::clamp(static_cast<int>(std::floor(std::log2(y / key))), kEvLowest, kEvHighest);
    return {displayed > y ? EvKind::Lifted : EvKind::Compressed, stop};
}

Rgb evColour(const EvClass& ev) {
    if (ev.kind == EvKind::Burnt) return {1.0, 1.0, 1.0};
    if (ev.kind == EvKind::Black) return {0.0, 0.0, 0.0};
    Rgb colour = colourScale(static_cast<double>(ev.stop - kEvLowest) / (kEvHighest - kEvLowest) * kEvScaleTop);
    if (ev.kind == EvKind::Compressed) {
        for (double& c : colour) c *= 0.5;
    }
    return colour;
}

int legendHeight(int height) { return std::max(2, height / 20); }

} // namespace views

ViewService::ViewService(const ShaderManager& shaders, View initial) : shaders_(shaders), current_(initial) {}

ViewService::~ViewService() {
    if (program_ != 0) glDeleteProgram(program_);
}

bool ViewService::available(View view) const {
    if (!discovered_) return true;
    const bool key = luminance_.texture != 0 && luminanceSmallest_.width == 1 && luminanceSmallest_.height == 1;
    switch (view) {
    case View::Final: return true;
    case View::Hdr: return accumulation_.texture != 0;
    case View::Luminance: return luminance_.texture != 0;
    case View::Key: return key;
    case View::Bloom0: return bloom0_.texture != 0;
    case View::Bloom1: return bloom1_.texture != 0;
    case View::Blur: return blur_.texture != 0;
    case View::Ev: return key && accumulation_.texture != 0;
    case View::Nan: return accumulation_.texture != 0;
    }
    return false;
}

std::vector<View> ViewService::availableViews() const {
    std::vector<View> views;
    for (int i = 0; i < kViewCount; ++i) {
        if (available(static_cast<View>(i))) views.push_back(static_cast<View>(i));
    }
    return views;
}

bool ViewService::select(View view) {
    if (!available(view)) return false;
    current_ = view;
    return true;
}

void ViewService::cycle(int direction) {
    int index = static_cast<int>(current_);
    for (int step = 0; step < kViewCount; ++step) {
        index = (index + direction + kViewCount) % kViewCount;
        if (select(static_cast<View>(index))) return;
    }
}

void ViewService::discover(int width, int height) {
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    GLint levels = 0;
    GLuint texture = boundTexture(kAccumulationUnit, levels);
    accumulation_ = levelOf(kAccumulationUnit, texture, 0);
    texture = boundTexture(kLuminanceUnit, levels);
    luminance_ = levelOf(kLuminanceUnit, texture, 0);
    luminanceSmallest_ = levelOf(kLuminanceUnit, texture, std::max(levels - 1, 0));
    const GLuint bloom = boundTexture(kBloomUnit, levels);
    bloom0_ = levelOf(kBloomUnit, bloom, 0);
    bloom1_ = levelOf(kBloomUnit, bloom, 1);
    blur_ = findBlurTarget(bloom1_, bloom);
    // A luminance texture the size of the frame is the stage's; anything else on unit 16 is not.
    if (luminance_.width != width || luminance_.height != height) luminance_ = luminanceSmallest_ = ViewTarget{};
    if (bloom0_.width != width || bloom0_.height != height) bloom0_ = bloom1_ = blur_ = ViewTarget{};
    luminanceMapped_ = luminance_.format != GL_R16F && luminance_.format != GL_R32F;
    glActiveTexture(static_cast<GLenum>(active));

    // The white point: extras/ makes it a uniform of the final program (step 37); the stages hold
    // the tutorial's literal 0.22.
    ywhite_ = views::kYwhite;
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (program != 0) {
        const GLint location = glGetUniformLocation(static_cast<GLuint>(program), "fYwhite");
        if (location >= 0) {
            GLfloat value = 0.0f;
            glGetUniformfv(static_cast<GLuint>(program), location, &value);
            if (value > 0.0f) ywhite_ = value;
        }
    }
    discovered_ = true;
}

void ViewService::readKey() {
    // extras' white point may differ from the tutorial's, which readSceneKey() assumes.
    const std::optional<SceneKey> key = luminanceSmallest_.texture != 0 ? readSceneKey() : std::nullopt;
    key_ = !key ? 0.0 : key->rangeMapped ? views::keyFromMapped(key->stored, ywhite_) : key->ya;
}

void ViewService::countNonFinite() {
    const std::size_t accumulation = countNonFiniteTexels(accumulation_, true);
    const std::size_t luminance = countNonFiniteTexels(luminance_, false);
    const std::size_t bloom0 = countNonFiniteTexels(bloom0_, false);
    const std::size_t bloom1 = countNonFiniteTexels(bloom1_, false);
    const std::size_t blur = countNonFiniteTexels(blur_, false);
    caption_ = "nan: " + std::to_string(accumulation + luminance + bloom0 + bloom1 + blur) +
               " non-finite texels, shown in magenta over the dimmed hdr view (accumulation " +
               std::to_string(accumulation);
    if (luminance_.texture != 0) caption_ += ", luminance " + std::to_string(luminance);
    if (bloom0_.texture != 0) caption_ += ", bloom0 " + std::to_string(bloom0);
    if (bloom1_.texture != 0) caption_ += ", bloom1 " + std::to_string(bloom1);
    if (blur_.texture != 0) caption_ += ", blur " + std::to_string(blur);
    caption_ += ")";
}

void ViewService::updateCaption() {
    const double dg = key_ > 0.0 ? views::middleGrey(key_) : 0.0;
    switch (current_) {
    case View::Final: caption_ = "final: the stage's own frame"; break;
    case View::Hdr:
        caption_ = "hdr: accumulation (" + describe(accumulation_) + ") x " + number(views::kHdrExposure) +
                   ", clamped, ^(1/2.2); white = at or above the bloom threshold " + number(views::kBloomThreshold);
        break;
    case View::Luminance:
        caption_ = "luminance: " + describe(luminance_) +
                   (luminanceMapped_ ? ", range-mapped log luminance" : ", log luminance range-mapped for display") +
                   " on the colour scale (strip at the bottom): 0 = log(1e-8) dark blue ... 1 = log(Yw = " +
                   number(ywhite_) + ") white";
        break;
    case View::Key:
        caption_ = "key: smallest level (" + describe(luminanceSmallest_) + ") as a swatch on the colour scale at " +
                   number(views::rangeMap(key_, ywhite_)) + ": Ya = " + number(key_) + ", dg = " + number(dg);
        break;
    case View::Bloom0:
    case View::Bloom1:
    case View::Blur: {
        const ViewTarget& target = current_ == View::Bloom0 ? bloom0_ : current_ == View::Bloom1 ? bloom1_ : blur_;
        caption_ = std::string(viewName(current_)) + ": " + describe(target) + " x " + number(views::kBloomExposure) +
                   ", clamped, ^(1/2.2)";
        break;
    }
    case View::Ev:
        caption_ = "ev: HDR luminance in stops around Ya = " + number(key_) + " (dg = " + number(dg) + "), bands " +
                   std::to_string(views::kEvLowest) + " (dark blue) to +" + std::to_string(views::kEvHighest) +
                   " (red) on the colour scale, full where the tone map lifts a pixel, half where it compresses it; "
                   "white: burnt (Y >= Yw Ya / dg = " +
                   number(ywhite_ * key_ / dg) + "), black: 8-bit black; legend strip at the bottom";
        break;
    case View::Nan: countNonFinite(); break;
    }
}

void ViewService::draw(const FullScreenQuad& quad, int width, int height) {
    if (current_ == View::Final && commandLineChecked_ && !thumbnails_) {
        caption_ = "final: the stage's own frame";
        return;
    }
    discover(width, height);
    if (!commandLineChecked_) {
        commandLineChecked_ = true;
        if (!available(current_)) {
            std::string names;
            for (View view : availableViews()) names += (names.empty() ? "" : ", ") + std::string(viewName(view));
            throw UsageError(std::string("--view ") + viewName(current_) + ": this stage has no " +
                             viewName(current_) + " (its views: " + names + ")");
        }
    }
    if (!available(current_)) current_ = View::Final; // e.g. exercise 40 rebuilt the chain
    if (current_ == View::Key || current_ == View::Ev) readKey();
    updateCaption();
    if (current_ != View::Final && caption_ != printedCaption_) {
        std::cout << "view " << caption_ << "\n";
        printedCaption_ = caption_;
    }
    if (current_ == View::Final && !thumbnails_) return;
    if (program_ == 0) program_ = shaders_.createProgram({"FullScreenQuad.vert", "views/View.frag"});

    GLint active = 0;
    GLint previousProgram = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
    const GLboolean blend = glIsEnabled(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);

    const std::array<const ViewTarget*, kSampledTargets> targets = {&accumulation_, &luminance_, &bloom0_, &bloom1_,
                                                                    &blur_};
    std::array<GLuint, kSampledTargets> views{};
    GLint present = 0;
    for (int i = 0; i < kSampledTargets; ++i) {
        views[static_cast<std::size_t>(i)] = bindLevelView(kFirstViewUnit + static_cast<GLuint>(i), *targets[i]);
        if (targets[i]->texture != 0) present |= 1 << i;
    }

    const double dg = key_ > 0.0 ? views::middleGrey(key_) : 0.0;
    glUseProgram(program_);
    glUniform1f(kKeyPosition, static_cast<float>(views::rangeMap(key_, ywhite_)));
    glUniform1f(kKey, static_cast<float>(key_));
    glUniform1f(kDg, static_cast<float>(dg));
    glUniform1f(kYwhite, static_cast<float>(ywhite_));
    glUniform1i(kMapped, luminanceMapped_ ? 1 : 0);
    glUniform1i(kPresent, present);
    for (int i = 0; i < views::kScaleStops; ++i) {
        const views::Rgb& stop = views::colourScaleStops()[static_cast<std::size_t>(i)];
        glUniform3f(kScale + i, static_cast<float>(stop[0]), static_cast<float>(stop[1]), static_cast<float>(stop[2]));
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    quad.bind();
    if (current_ != View::Final) drawPass(current_, 0, 0, width, height, views::legendHeight(height));
    if (thumbnails_) drawThumbnails(width, height);
    glViewport(0, 0, width, height);

    for (int i = 0; i < kSampledTargets; ++i) {
        glActiveTexture(GL_TEXTURE0 + kFirstViewUnit + static_cast<GLuint>(i));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glDeleteTextures(kSampledTargets, views.data());
    glUseProgram(static_cast<GLuint>(previousProgram));
    glActiveTexture(static_cast<GLenum>(active));
    if (depthTest == GL_TRUE) glEnable(GL_DEPTH_TEST);
    if (blend == GL_TRUE) glEnable(GL_BLEND);
}

void ViewService::drawPass(View view, int x, int y, int width, int height, int legend) const {
    const bool bloomView = view == View::Bloom0 || view == View::Bloom1 || view == View::Blur;
    glViewport(x, y, width, height);
    glUniform1i(kMode, static_cast<GLint>(view));
    glUniform2i(kOrigin, x, y);
    glUniform2i(kSize, width, height);
    glUniform1f(kExposure, static_cast<float>(bloomView ? views::kBloomExposure : views::kHdrExposure));
    glUniform1i(kLegend, legend);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, nullptr);
}

void ViewService::drawThumbnails(int width, int height) const {
    // Five slots along the bottom, each a fifth of the width with the frame's aspect, and a label
    // band above each: the target's format and size in the built-in 3x5 font at twice its size.
    const int slotWidth = width / kSampledTargets;
    const int slotHeight = std::max(1, slotWidth * height / std::max(width, 1));
    const int labelHeight = kGlyphRows * kLabelScale + 2 * kLabelScale;
    if (slotWidth < 8 || slotHeight + labelHeight > height) return;
    const std::array<std::pair<View, const ViewTarget*>, kSampledTargets> slots = {
        {{View::Hdr, &accumulation_}, {View::Luminance, &luminance_}, {View::Bloom0, &bloom0_},
         {View::Bloom1, &bloom1_}, {View::Blur, &blur_}}};
    int slot = 0;
    for (const auto& [view, target] : slots) {
        if (target->texture == 0) continue;
        const int x = slot * slotWidth;
        drawPass(view, x, 0, slotWidth, slotHeight, 0);
        std::array<GLint, kLabelChars> codes{};
        const std::string label = formatName(target->format).substr(3) + " " + std::to_string(target->width) + "x" +
                                  std::to_string(target->height);
        for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = i < label.size() ? glyphIndex(label[i]) : -1;
        glUniform1iv(kText, kLabelChars, codes.data());
        glUniform1i(kTextScale, kLabelScale);
        drawPass(View::Final, x, slotHeight, slotWidth, labelHeight, 0); // mode 0 draws the label
        ++slot;
    }
}

void ViewKeys::update(ViewService& views) {
    const bool shift = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                       glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    if (edges_.pressed(window_, GLFW_KEY_V)) views.cycle(shift ? -1 : 1);
    if (edges_.pressed(window_, GLFW_KEY_T)) views.showThumbnails(!views.thumbnails());
}

} // namespace t10
