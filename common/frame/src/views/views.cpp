// The view selector (see views.hpp): finds the chain's targets from what the stage left bound,
// samples each through a texture view of the level it shows, and draws one full-screen pass over
// framebuffer 0 with common/shaders/views/View.frag.
#include "t10/views.hpp"

#include "t10/error.hpp"
#include "t10/quad.hpp"
#include "t10/scene_key.hpp"
#include "t10/shader.hpp"

#include <CLI/CLI.hpp>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace t10 {

namespace {

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

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.5g", value);
    return text;
}

} // namespace

void addViewOptions(CLI::App& cli, ViewSettings& settings) {
    CLI::Option_group* group = cli.add_option_group("Views", "Buffers of the chain shown instead of the final frame");
    group->add_option("--view", settings.view,
                      "What to show: " + allViewNames() + " (default final; V cycles in a window)");
    group->add_flag("--thumbnails", settings.thumbnails, "Draw a strip of thumbnails of every target of the chain "
                                                         "along the bottom, each labelled (T toggles in a window)");
    group->callback([&settings] {
        if (!findView(settings.view)) {
            throw UsageError("--view " + settings.view + ": unknown view (choose from " + allViewNames() + ")");
        }
    });
}

ViewService::ViewService(const ShaderManager& shaders, View initial) : shaders_(shaders), current_(initial) {}

ViewService::~ViewService() {
    if (program_ != 0) glDeleteProgram(program_);
}

bool ViewService::available(View view) const {
    if (!discovered_) return true;
    const bool key =
        chain_.luminance.texture != 0 && chain_.luminanceSmallest.width == 1 && chain_.luminanceSmallest.height == 1;
    switch (view) {
    case View::Final: return true;
    case View::Hdr: return chain_.accumulation.texture != 0;
    case View::Luminance: return chain_.luminance.texture != 0;
    case View::Key: return key;
    case View::Bloom0: return chain_.bloom0.texture != 0;
    case View::Bloom1: return chain_.bloom1.texture != 0;
    case View::Blur: return chain_.blur.texture != 0;
    case View::Ev: return key && chain_.accumulation.texture != 0;
    case View::Nan: return chain_.accumulation.texture != 0;
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

void ViewService::readKey() {
    // extras' white point may differ from the tutorial's, which readSceneKey() assumes.
    const std::optional<SceneKey> key = chain_.luminanceSmallest.texture != 0 ? readSceneKey() : std::nullopt;
    key_ = !key ? 0.0 : key->rangeMapped ? views::keyFromMapped(key->stored, chain_.ywhite) : key->ya;
}

void ViewService::countNonFinite() {
    const std::size_t accumulation = countNonFiniteTexels(chain_.accumulation, true);
    const std::size_t luminance = countNonFiniteTexels(chain_.luminance, false);
    const std::size_t bloom0 = countNonFiniteTexels(chain_.bloom0, false);
    const std::size_t bloom1 = countNonFiniteTexels(chain_.bloom1, false);
    const std::size_t blur = countNonFiniteTexels(chain_.blur, false);
    caption_ = "nan: " + std::to_string(accumulation + luminance + bloom0 + bloom1 + blur) +
               " non-finite texels, shown in magenta over the dimmed hdr view (accumulation " +
               std::to_string(accumulation);
    if (chain_.luminance.texture != 0) caption_ += ", luminance " + std::to_string(luminance);
    if (chain_.bloom0.texture != 0) caption_ += ", bloom0 " + std::to_string(bloom0);
    if (chain_.bloom1.texture != 0) caption_ += ", bloom1 " + std::to_string(bloom1);
    if (chain_.blur.texture != 0) caption_ += ", blur " + std::to_string(blur);
    caption_ += ")";
}

void ViewService::updateCaption() {
    const double dg = key_ > 0.0 ? views::middleGrey(key_) : 0.0;
    switch (current_) {
    case View::Final: caption_ = "final: the stage's own frame"; break;
    case View::Hdr:
        caption_ = "hdr: accumulation (" + describe(chain_.accumulation) + ") x " + number(views::kHdrExposure) +
                   ", clamped, ^(1/2.2); white = at or above the bloom threshold " + number(views::kBloomThreshold);
        break;
    case View::Luminance:
        caption_ = "luminance: " + describe(chain_.luminance) +
                   (chain_.luminanceMapped ? ", range-mapped log luminance"
                                           : ", log luminance range-mapped for display") +
                   " on the colour scale (strip at the bottom): 0 = log(1e-8) dark blue ... 1 = log(Yw = " +
                   number(chain_.ywhite) + ") white";
        break;
    case View::Key:
        caption_ = "key: smallest level (" + describe(chain_.luminanceSmallest) +
                   ") as a swatch on the colour scale at " + number(views::rangeMap(key_, chain_.ywhite)) +
                   ": Ya = " + number(key_) + ", dg = " + number(dg) +
                   "; the strip at the bottom is the scale, the key marked black over white";
        break;
    case View::Bloom0:
    case View::Bloom1:
    case View::Blur: {
        const ViewTarget& target = current_ == View::Bloom0   ? chain_.bloom0
                                   : current_ == View::Bloom1 ? chain_.bloom1
                                                              : chain_.blur;
        caption_ = std::string(viewName(current_)) + ": " + describe(target) + " x " + number(views::kBloomExposure) +
                   ", clamped, ^(1/2.2)";
        break;
    }
    case View::Ev:
        caption_ = "ev: HDR luminance in stops around Ya = " + number(key_) + " (dg = " + number(dg) + "), bands " +
                   std::to_string(views::kEvLowest) + " (dark blue) to +" + std::to_string(views::kEvHighest) +
                   " (red) on the colour scale, full where the tone map lifts a pixel, half where it compresses it; "
                   "white: burnt (Y >= Yw Ya / dg = " +
                   number(chain_.ywhite * key_ / dg) + "), black: 8-bit black; legend strip at the bottom";
        break;
    case View::Nan: countNonFinite(); break;
    }
}

void ViewService::draw(const FullScreenQuad& quad, int width, int height) {
    if (current_ == View::Final && commandLineChecked_ && !thumbnails_) {
        caption_ = "final: the stage's own frame";
        return;
    }
    chain_ = discoverChain(width, height);
    discovered_ = true;
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

    const std::array<const ViewTarget*, views::kSampledTargets> targets = {
        &chain_.accumulation, &chain_.luminance, &chain_.bloom0, &chain_.bloom1, &chain_.blur};
    std::array<GLuint, views::kSampledTargets> views{};
    GLint present = 0;
    for (int i = 0; i < views::kSampledTargets; ++i) {
        views[static_cast<std::size_t>(i)] = bindLevelView(views::kFirstViewUnit + static_cast<GLuint>(i), *targets[i]);
        if (targets[i]->texture != 0) present |= 1 << i;
    }

    const double dg = key_ > 0.0 ? views::middleGrey(key_) : 0.0;
    glUseProgram(program_);
    glUniform1f(kKeyPosition, static_cast<float>(views::rangeMap(key_, chain_.ywhite)));
    glUniform1f(kKey, static_cast<float>(key_));
    glUniform1f(kDg, static_cast<float>(dg));
    glUniform1f(kYwhite, static_cast<float>(chain_.ywhite));
    glUniform1i(kMapped, chain_.luminanceMapped ? 1 : 0);
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

    for (int i = 0; i < views::kSampledTargets; ++i) {
        glActiveTexture(GL_TEXTURE0 + views::kFirstViewUnit + static_cast<GLuint>(i));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glDeleteTextures(views::kSampledTargets, views.data());
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
    const int slotWidth = width / views::kSampledTargets;
    const int slotHeight = std::max(1, slotWidth * height / std::max(width, 1));
    const int labelHeight = kGlyphRows * kLabelScale + 2 * kLabelScale;
    if (slotWidth < 8 || slotHeight + labelHeight > height) return;
    const std::array<std::pair<View, const ViewTarget*>, views::kSampledTargets> slots = {
        {{View::Hdr, &chain_.accumulation}, {View::Luminance, &chain_.luminance}, {View::Bloom0, &chain_.bloom0},
         {View::Bloom1, &chain_.bloom1}, {View::Blur, &chain_.blur}}};
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
