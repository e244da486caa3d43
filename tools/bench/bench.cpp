// t10-bench (`make bench`): the tutorial's post-process chain against the chains a student would try
// instead, on the same HDR frames, timed with GL_TIME_ELAPSED queries, interleaved and repeated.
//
//   tutorial        Part 3 as it is: its own shader files, its host sequence (luminance pass, mip
//                   chain, five pass pairs of the 5-tap Gaussian at half resolution, final pass)
//   keyonce         the same with the key math done once in the vertex shader (KeyOnce.vert)
//   lo_full         LearnOpenGL-style bloom: RGBA16F bright pass, 10 ping-pong passes of a 9-tap
//                   Gaussian, exposure tone map; full resolution
//   lo_half         the same at half resolution
//   tap13           the tutorial's luminance pass and key, its blur replaced by a 13-tap downsample
//                   and tent upsample chain down to 1/64
//   key_mip         the key alone, three ways: the tutorial's mip chain, a compute reduction
//   key_compute     (common/optional/src/exact_key.cpp) and a power-of-two luminance target (padded with
//   key_pot         zeros and rescaled), each with its error against the exact double-precision mean
//
// It prints the ratios to the tutorial's chain, the log-log slope of each chain's time against
// the pixel count, the texture lookups and bytes of each chain, the key errors, the renderer and
// the machine; it writes bench.csv, keys.csv and machine.txt into the output folder.
#include "reference.hpp"
#include "t10/context.hpp"
#include "t10/contract.hpp"
#include "t10/args.hpp"
#include "t10/error.hpp"
#include "t10/exact_key.hpp"
#include "t10/file.hpp"
#include "t10/gl_errors.hpp"
#include "t10/gltf_scene.hpp"
#include "t10/quad.hpp"
#include "t10/readback.hpp"
#include "t10/scene.hpp"
#include "t10/stats.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using t10::Error;

namespace contract = t10::contract;
constexpr GLuint kUboBinding = contract::kInvResolutionBinding;
constexpr GLuint kLuminanceUnit = contract::kLuminanceKeyUnit;
constexpr GLuint kBloomUnit = contract::kBloomUnit;
constexpr int kBlurPasses = contract::kBlurPasses; // the tutorial's pass pairs
constexpr int kLoPasses = 10;         // LearnOpenGL's ping-pong passes
constexpr int kTapLevels = 6;         // 13-tap chain: 1/2 .. 1/64
constexpr int kWarmUpRuns = 1;        // untimed runs of every chain before the timed ones

// Bytes per texel of the formats the chains use.
constexpr double kRgba16f = 8.0, kR11g11b10f = 4.0, kR16 = 2.0, kRgba8 = 4.0;

struct Size {
    int width;
    int height;
    double pixels() const { return double(width) * double(height); }
    std::string name() const { return std::to_string(width) + "x" + std::to_string(height); }
};

// What a chain costs, counted per pass from its shaders: texture lookups (one per texture() call
// per fragment, a bilinear tap counting as one) and bytes (every source texel read once plus every
// target texel written once: the least memory traffic, what a GPU with caches approaches).
struct Cost {
    double lookups = 0.0;
    double bytes = 0.0;
};

// Times the passes of one run with GL_TIME_ELAPSED queries (one at a time, as GL allows).
class PassClock {
public:
    void begin(const char* pass) {
        if (open_) glEndQuery(GL_TIME_ELAPSED);
        GLuint query = 0;
        glGenQueries(1, &query);
        queries_.emplace_back(pass, query);
        glBeginQuery(GL_TIME_ELAPSED, query);
        open_ = true;
    }
    // Ends the last pass, waits, returns the time of each named pass in milliseconds (in the order
    // they first ran) and forgets the queries.
    std::vector<std::pair<std::string, double>> finish() {
        if (open_) glEndQuery(GL_TIME_ELAPSED);
        open_ = false;
        std::vector<std::pair<std::string, double>> passes;
        for (const auto& [pass, query] : queries_) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
            auto found = std::find_if(passes.begin(), passes.end(), [&](const auto& p) { return p.first == pass; });
            if (found == passes.end()) passes.emplace_back(pass, double(ns) / 1e6);
            else found->second += double(ns) / 1e6;
            glDeleteQueries(1, &query);
        }
        queries_.clear();
        return passes;
    }

private:
    std::vector<std::pair<std::string, GLuint>> queries_;
    bool open_ = false;
};

GLuint makeTexture2D(GLenum format, int levels, int width, int height, GLenum filter) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexStorage2D(GL_TEXTURE_2D, levels, format, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter == GL_LINEAR_MIPMAP_NEAREST ? GL_LINEAR : filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

GLuint makeFramebuffer(std::initializer_list<std::pair<GLuint, int>> attachments, const char* name) {
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    std::vector<GLenum> buffers;
    for (const auto& [texture, level] : attachments) {
        const auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffers.size());
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, level);
        buffers.push_back(attachment);
    }
    glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error(std::string("bench: framebuffer ") + name + " is incomplete");
    return framebuffer;
}

int fullMipLevels(int width, int height) { return int(std::floor(std::log2(std::max(width, height)))) + 1; }
int nextPowerOfTwo(int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
}

// Sum of the texels of every level below level 0 of a full chain (what glGenerateMipmap writes).
double mipTexels(int width, int height) {
    double texels = 0.0;
    while (width > 1 || height > 1) {
        width = std::max(width / 2, 1);
        height = std::max(height / 2, 1);
        texels += double(width) * double(height);
    }
    return texels;
}

// Every program the chains use. The tutorial's come from its own folder, unchanged.
struct Programs {
    GLuint init, gauss, post;                   // tutorial10_part3_gaussian
    GLuint loBright, loBlur, loFinal, down, up; // tools/bench/shaders
    GLuint keyOnce;

    Programs(const t10::ShaderManager& tutorial, const t10::ShaderManager& bench) {
        init = tutorial.createProgram({"FullScreenQuad.vert", "PostProcessInit.frag"});
        gauss = tutorial.createProgram({"FullScreenQuad.vert", "Gauss.frag"});
        post = tutorial.createProgram({"FullScreenQuad.vert", "PostProcess.frag"});
        loBright = bench.createProgram({"FullScreenQuad.vert", "LoBright.frag"});
        loBlur = bench.createProgram({"FullScreenQuad.vert", "LoBlur.frag"});
        loFinal = bench.createProgram({"FullScreenQuad.vert", "LoFinal.frag"});
        down = bench.createProgram({"FullScreenQuad.vert", "Down13.frag"});
        up = bench.createProgram({"FullScreenQuad.vert", "UpTent.frag"});
        keyOnce = bench.createProgram({"KeyOnce.vert", "KeyOnce.frag"});
    }
    ~Programs() {
        for (GLuint p : {init, gauss, post, loBright, loBlur, loFinal, down, up, keyOnce}) glDeleteProgram(p);
    }
    Programs(const Programs&) = delete;
    Programs& operator=(const Programs&) = delete;
};

// The size-dependent objects of every chain, created once per size.
class Targets {
public:
    Targets(Size size, GLuint accumulation) : s_(size), accumulation_(accumulation) {
        const int w = s_.width, h = s_.height, hw = w / 2, hh = h / 2;
        glGenBuffers(1, &ubo_);
        glBindBufferBase(GL_UNIFORM_BUFFER, kUboBinding, ubo_);
        glBufferData(GL_UNIFORM_BUFFER, 2 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
        // The tutorial's objects, as Part 3's GL_Init makes them.
        lumLevels_ = fullMipLevels(w, h);
        luminance_ = own(makeTexture2D(GL_R16, lumLevels_, w, h, GL_LINEAR_MIPMAP_NEAREST));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        bloom_ = own(makeTexture2D(GL_R11F_G11F_B10F, 2, w, h, GL_LINEAR_MIPMAP_NEAREST));
        blur_ = own(makeTexture2D(GL_R11F_G11F_B10F, 1, hw, hh, GL_LINEAR));
        fboPost_ = ownFbo(makeFramebuffer({{luminance_, 0}, {bloom_, 0}}, "post"));
        fboBlur_ = ownFbo(makeFramebuffer({{blur_, 0}}, "blur"));
        fboBloom_ = ownFbo(makeFramebuffer({{bloom_, 1}}, "bloom level 1"));
        display_ = own(makeTexture2D(GL_RGBA8, 1, w, h, GL_NEAREST));
        fboDisplay_ = ownFbo(makeFramebuffer({{display_, 0}}, "display"));
        // Key methods: the luminance alone (the bloom output has no attachment and is dropped).
        fboKey_ = ownFbo(makeFramebuffer({{luminance_, 0}}, "key"));
        potW_ = nextPowerOfTwo(w);
        potH_ = nextPowerOfTwo(h);
        potLevels_ = fullMipLevels(potW_, potH_);
        pot_ = own(makeTexture2D(GL_R16, potLevels_, potW_, potH_, GL_LINEAR_MIPMAP_NEAREST));
        fboPot_ = ownFbo(makeFramebuffer({{pot_, 0}}, "power-of-two key"));
        // LearnOpenGL-style: bright pass and two ping-pong targets, full and half resolution.
        for (int half = 0; half < 2; ++half) {
            const int lw = half ? hw : w, lh = half ? hh : h;
            for (int i = 0; i < 2; ++i) {
                lo_[half][i] = own(makeTexture2D(GL_RGBA16F, 1, lw, lh, GL_LINEAR));
                fboLo_[half][i] = ownFbo(makeFramebuffer({{lo_[half][i], 0}}, "LearnOpenGL ping-pong"));
            }
        }
        // 13-tap chain levels 1/2 .. 1/64.
        for (int i = 0; i < kTapLevels; ++i) {
            const int lw = std::max(w >> (i + 1), 1), lh = std::max(h >> (i + 1), 1);
            tapSize_[i] = {lw, lh};
            tap_[i] = own(makeTexture2D(GL_R11F_G11F_B10F, 1, lw, lh, GL_LINEAR));
            fboTap_[i] = ownFbo(makeFramebuffer({{tap_[i], 0}}, "13-tap level"));
        }
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    }
    ~Targets() {
        for (GLuint t : textures_) glDeleteTextures(1, &t);
        for (GLuint f : framebuffers_) glDeleteFramebuffers(1, &f);
        glDeleteBuffers(1, &ubo_);
    }
    Targets(const Targets&) = delete;
    Targets& operator=(const Targets&) = delete;

    Size s_;
    GLuint accumulation_;
    GLuint ubo_ = 0;
    int lumLevels_ = 1, potLevels_ = 1, potW_ = 1, potH_ = 1;
    GLuint luminance_ = 0, bloom_ = 0, blur_ = 0, display_ = 0, pot_ = 0;
    GLuint fboPost_ = 0, fboBlur_ = 0, fboBloom_ = 0, fboDisplay_ = 0, fboKey_ = 0, fboPot_ = 0;
    GLuint lo_[2][2] = {}, fboLo_[2][2] = {};
    GLuint tap_[kTapLevels] = {}, fboTap_[kTapLevels] = {};
    Size tapSize_[kTapLevels] = {};

private:
    GLuint own(GLuint texture) { textures_.push_back(texture); return texture; }
    GLuint ownFbo(GLuint framebuffer) { framebuffers_.push_back(framebuffer); return framebuffer; }
    std::vector<GLuint> textures_;
    std::vector<GLuint> framebuffers_;
};

void setInvResolution(const Targets& t, int width, int height) {
    const float inv[2] = {1.0f / float(width), 1.0f / float(height)};
    glBindBuffer(GL_UNIFORM_BUFFER, t.ubo_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof inv, inv);
}

void bindUnit(GLuint unit, GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture);
}

void draw() { glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, nullptr); }

// One chain: runs its passes (each begun on the clock) and adds its cost when `cost` is given.
using Chain = std::function<void(Targets&, const Programs&, PassClock&, Cost*)>;

void add(Cost* cost, double lookups, double bytes) {
    if (cost) {
        cost->lookups += lookups;
        cost->bytes += bytes;
    }
}

// --- The tutorial's passes, in Part 3's order ----------------------------------------------------

void tutorialLuminance(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    const double n = t.s_.pixels();
    clock.begin("luminance");
    setInvResolution(t, t.s_.width, t.s_.height);
    glViewport(0, 0, t.s_.width, t.s_.height);
    glUseProgram(p.init);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboPost_);
    glClear(GL_COLOR_BUFFER_BIT);
    draw();
    add(cost, n, n * (kRgba16f + kR16 + kR11g11b10f));
}

void tutorialMipChain(Targets& t, PassClock& clock, Cost* cost) {
    clock.begin("mip chain");
    bindUnit(kLuminanceUnit, t.luminance_);
    glGenerateMipmap(GL_TEXTURE_2D);
    const double texels = mipTexels(t.s_.width, t.s_.height);
    add(cost, 4.0 * texels, kR16 * (texels + t.s_.pixels()));
}

void tutorialBlur(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    const int hw = t.s_.width / 2, hh = t.s_.height / 2;
    const double half = double(hw) * double(hh);
    clock.begin("blur");
    bindUnit(kBloomUnit, t.bloom_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glViewport(0, 0, hw, hh);
    setInvResolution(t, hw, hh);
    glUseProgram(p.gauss);
    const GLuint horizontal = 0, vertical = 1;
    for (int i = 0; i < kBlurPasses; ++i) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboBlur_);
        glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &horizontal);
        glClear(GL_COLOR_BUFFER_BIT);
        draw();
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboBloom_);
        glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &vertical);
        glBindTexture(GL_TEXTURE_2D, t.blur_);
        glClear(GL_COLOR_BUFFER_BIT);
        draw();
        glBindTexture(GL_TEXTURE_2D, t.bloom_);
        if (i == 0) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
        }
        // The first pass reads level 0 (full resolution), the others half-resolution images.
        const double sourceTexels = i == 0 ? t.s_.pixels() : half;
        add(cost, 2 * 5 * half, kR11g11b10f * (sourceTexels + 3 * half));
    }
    glViewport(0, 0, t.s_.width, t.s_.height);
    setInvResolution(t, t.s_.width, t.s_.height);
}

void finalPass(Targets& t, GLuint program, int lookupsPerPixel, PassClock& clock, Cost* cost) {
    const double n = t.s_.pixels();
    clock.begin("final");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboDisplay_);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(program);
    draw();
    const double bloomTexels = double(t.s_.width / 2) * double(t.s_.height / 2);
    add(cost, lookupsPerPixel * n, n * (kRgba16f + kRgba8) + kR11g11b10f * bloomTexels + kR16);
}

void tutorialChain(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    tutorialLuminance(t, p, clock, cost);
    tutorialMipChain(t, clock, cost);
    tutorialBlur(t, p, clock, cost);
    finalPass(t, p.post, 3, clock, cost);
}

void keyOnceChain(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    tutorialLuminance(t, p, clock, cost);
    tutorialMipChain(t, clock, cost);
    tutorialBlur(t, p, clock, cost);
    finalPass(t, p.keyOnce, 2, clock, cost);
}

// --- LearnOpenGL-style bloom ----------------------------------------------------------------------

void learnOpenGlChain(Targets& t, const Programs& p, PassClock& clock, Cost* cost, bool half) {
    const int w = t.s_.width, h = t.s_.height;
    const int lw = half ? w / 2 : w, lh = half ? h / 2 : h;
    const double n = t.s_.pixels(), m = double(lw) * double(lh);
    clock.begin("bright pass");
    glViewport(0, 0, lw, lh);
    glUseProgram(p.loBright);
    glUniform2f(0, 1.0f / float(lw), 1.0f / float(lh));
    bindUnit(0, t.accumulation_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboLo_[half][0]);
    draw();
    add(cost, m, kRgba16f * (n + m));

    clock.begin("blur");
    glUseProgram(p.loBlur);
    glUniform2f(0, 1.0f / float(lw), 1.0f / float(lh));
    for (int i = 0; i < kLoPasses; ++i) {
        const bool horizontal = i % 2 == 0;
        glUniform2f(1, horizontal ? 1.0f / float(lw) : 0.0f, horizontal ? 0.0f : 1.0f / float(lh));
        bindUnit(0, t.lo_[half][i % 2]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboLo_[half][(i + 1) % 2]);
        draw();
        add(cost, 9 * m, 2 * kRgba16f * m);
    }

    clock.begin("final");
    glViewport(0, 0, w, h);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboDisplay_);
    glUseProgram(p.loFinal);
    glUniform2f(0, 1.0f / float(w), 1.0f / float(h));
    bindUnit(0, t.accumulation_);
    bindUnit(1, t.lo_[half][kLoPasses % 2]);
    draw();
    add(cost, 2 * n, n * (kRgba16f + kRgba8) + kRgba16f * m);
}

// --- 13-tap downsample / tent upsample ------------------------------------------------------------

void tap13Chain(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    tutorialLuminance(t, p, clock, cost);
    tutorialMipChain(t, clock, cost);
    clock.begin("downsample");
    glUseProgram(p.down);
    bindUnit(kBloomUnit, t.bloom_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    for (int i = 0; i < kTapLevels; ++i) {
        const Size target = t.tapSize_[i];
        const Size source = i == 0 ? t.s_ : t.tapSize_[i - 1];
        glViewport(0, 0, target.width, target.height);
        glUniform2f(0, 1.0f / float(target.width), 1.0f / float(target.height));
        glUniform2f(1, 1.0f / float(source.width), 1.0f / float(source.height));
        bindUnit(0, i == 0 ? t.bloom_ : t.tap_[i - 1]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboTap_[i]);
        draw();
        add(cost, 13 * target.pixels(), kR11g11b10f * (source.pixels() + target.pixels()));
    }
    clock.begin("upsample");
    glUseProgram(p.up);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (int i = kTapLevels - 2; i >= 0; --i) {
        const Size target = t.tapSize_[i];
        const Size source = t.tapSize_[i + 1];
        glViewport(0, 0, target.width, target.height);
        glUniform2f(0, 1.0f / float(target.width), 1.0f / float(target.height));
        glUniform2f(1, 1.0f / float(source.width), 1.0f / float(source.height));
        bindUnit(0, t.tap_[i + 1]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.fboTap_[i]);
        draw();
        add(cost, 9 * target.pixels(), kR11g11b10f * (source.pixels() + 2 * target.pixels()));
    }
    glDisable(GL_BLEND);
    glViewport(0, 0, t.s_.width, t.s_.height);
    // The final pass reads the 1/2 level where Part 3 reads bloom level 1.
    bindUnit(kBloomUnit, t.tap_[0]);
    finalPass(t, p.post, 3, clock, cost);
}

// --- The key, three ways ----------------------------------------------------------------------------

void keyLuminance(Targets& t, const Programs& p, GLuint framebuffer, PassClock& clock, Cost* cost) {
    const double n = t.s_.pixels();
    clock.begin("luminance");
    setInvResolution(t, t.s_.width, t.s_.height);
    glViewport(0, 0, t.s_.width, t.s_.height);
    glUseProgram(p.init);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glClear(GL_COLOR_BUFFER_BIT);
    draw();
    add(cost, n, n * (kRgba16f + kR16));
}

void keyMipChain(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    keyLuminance(t, p, t.fboKey_, clock, cost);
    tutorialMipChain(t, clock, cost);
}

void keyComputeChain(Targets& t, const Programs& p, t10::ExactKey& exact, PassClock& clock, Cost* cost) {
    keyLuminance(t, p, t.fboKey_, clock, cost);
    clock.begin("reduction");
    exact.reduce(t.luminance_, t.s_.width, t.s_.height);
    add(cost, t.s_.pixels(), kR16 * t.s_.pixels() + 4.0 * t.s_.pixels() / 256.0);
}

void keyPotChain(Targets& t, const Programs& p, PassClock& clock, Cost* cost) {
    // The padding must be zero: the whole target is cleared, then the luminance pass covers the
    // frame's own width x height (the shader's UV comes from InvResolution, i.e. the frame's size).
    keyLuminance(t, p, t.fboPot_, clock, cost);
    clock.begin("mip chain");
    bindUnit(kLuminanceUnit, t.pot_);
    glGenerateMipmap(GL_TEXTURE_2D);
    const double texels = mipTexels(t.potW_, t.potH_);
    add(cost, 4.0 * texels, kR16 * (texels + double(t.potW_) * double(t.potH_)));
    bindUnit(kLuminanceUnit, t.luminance_);
}

// --- Measurement ---------------------------------------------------------------------------------

struct Result {
    std::string chain;
    Size size;
    std::vector<double> gpuMs;
    std::vector<double> wallMs;
    Cost cost;
    std::vector<std::pair<std::string, std::vector<double>>> passMs; // per pass, every timed run
};

using t10::median;

double readLastLevel(GLuint texture, int level) {
    const t10::ImageF image = t10::readTextureLevel(texture, level);
    if (image.width != 1 || image.height != 1) throw Error("bench: the key level is not 1x1");
    return double(image.data[0]);
}

struct KeyResult {
    std::string method;
    Size size;
    double mapped = 0.0; // range-mapped mean, as the final pass reads it
    double exact = 0.0;  // the same mean in double precision from the read-back frame
    double ya() const { return t10::ref::keyFromMapped(mapped); }
    double exactYa() const { return t10::ref::keyFromMapped(exact); }
    double relativeError() const { return std::abs(ya() - exactYa()) / exactYa(); }
};

struct Options {
    std::vector<Size> sizes;
    int repeats = 3;
    std::string outDir = "out/bench";
    bool smoke = false;
};

// The shared size parser with the bench's own limits (and its message, which names the option).
Size parseSize(const std::string& text) {
    try {
        const auto [width, height] = t10::parseSize(text, 2, 8192);
        return {width, height};
    } catch (const t10::UsageError&) {
        throw t10::UsageError("--sizes: '" + text + "' is not WxH with both sides in 2..8192");
    }
}

std::string machineDescription(const t10::Context& context) {
    std::ostringstream out;
    auto glText = [](GLenum name) {
        const auto* text = reinterpret_cast<const char*>(glGetString(name));
        return std::string(text ? text : "?");
    };
    out << "renderer: " << glText(GL_RENDERER) << "\n"
        << "version:  " << glText(GL_VERSION) << "\n"
        << "context:  " << context.description() << "\n";
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model;
    int cpus = 0;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0 && model.empty()) model = line.substr(line.find(':') + 2);
        if (line.rfind("processor", 0) == 0) ++cpus;
    }
    out << "cpu:      " << (model.empty() ? "?" : model) << " (" << cpus << " logical CPUs visible)\n";
    std::ifstream meminfo("/proc/meminfo");
    if (std::getline(meminfo, line)) {
        const std::size_t start = line.find_first_not_of(' ', line.find(':') + 1);
        out << "memory:   " << (start == std::string::npos ? "?" : line.substr(start)) << "\n";
    }
    return out.str();
}

// Least-squares slope of log(time) against log(pixels).
double logLogSlope(const std::vector<std::pair<double, double>>& points) {
    if (points.size() < 2) return NAN;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& [pixels, ms] : points) {
        const double x = std::log(pixels), y = std::log(ms);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double n = double(points.size());
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Every file is written whole or not at all (t10::writeFileAtomically).
void writeFile(const std::filesystem::path& path, const std::string& text) {
    t10::writeFileAtomically(path.string(), text.data(), text.size(), "the bench's results");
}

using NamedChains = std::vector<std::pair<std::string, Chain>>;

NamedChains makeChains(t10::ExactKey& exactKey) {
    return {
        {"tutorial", tutorialChain},
        {"keyonce", keyOnceChain},
        {"lo_full", [](Targets& t, const Programs& p, PassClock& c, Cost* k) { learnOpenGlChain(t, p, c, k, false); }},
        {"lo_half", [](Targets& t, const Programs& p, PassClock& c, Cost* k) { learnOpenGlChain(t, p, c, k, true); }},
        {"tap13", tap13Chain},
        {"key_mip", keyMipChain},
        {"key_compute",
         [&exactKey](Targets& t, const Programs& p, PassClock& c, Cost* k) { keyComputeChain(t, p, exactKey, c, k); }},
        {"key_pot", keyPotChain},
    };
}

// Puts Part 3's bloom back on its unit (the 13-tap chain's final pass reads a level of its own).
void restoreBloom(const Targets& targets) {
    bindUnit(kBloomUnit, targets.bloom_);
    glActiveTexture(GL_TEXTURE0);
}

// Every chain at one size, `repeats` times after the warm-up runs. Interleaved: every repeat runs
// every chain once, starting one chain later each time, so a slow spell on the shared machine does
// not land on one chain only.
std::vector<Result> timeChains(const Size& size, Targets& targets, const Programs& programs, const NamedChains& chains,
                               int repeats) {
    std::vector<Result> results;
    for (const auto& named : chains) results.push_back({named.first, size, {}, {}, {}, {}});
    PassClock clock;
    for (int run = 0; run < kWarmUpRuns + repeats; ++run) {
        for (std::size_t k = 0; k < chains.size(); ++k) {
            const std::size_t index = (k + std::size_t(run)) % chains.size();
            Result& result = results[index];
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            chains[index].second(targets, programs, clock, result.cost.lookups == 0.0 ? &result.cost : nullptr);
            const auto passes = clock.finish(); // waits for every query, so for the chain
            double gpu = 0.0;
            for (const auto& [pass, ms] : passes) gpu += ms;
            const double wall =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            restoreBloom(targets);
            if (run < kWarmUpRuns) continue;
            result.gpuMs.push_back(gpu);
            result.wallMs.push_back(wall);
            for (const auto& [pass, ms] : passes) {
                auto found = std::find_if(result.passMs.begin(), result.passMs.end(),
                                          [&](const auto& p) { return p.first == pass; });
                if (found == result.passMs.end()) result.passMs.push_back({pass, {ms}});
                else found->second.push_back(ms);
            }
        }
    }
    return results;
}

// The key-once final pass must draw the tutorial's frame (float rounding: one 8-bit step).
void checkKeyOnce(const Size& size, Targets& targets, const Programs& programs) {
    PassClock clock;
    tutorialChain(targets, programs, clock, nullptr);
    clock.finish();
    const t10::ImageF tutorialFrame = t10::readTextureLevel(targets.display_, 0);
    keyOnceChain(targets, programs, clock, nullptr);
    clock.finish();
    const t10::ImageF keyOnceFrame = t10::readTextureLevel(targets.display_, 0);
    double worst = 0.0;
    for (std::size_t i = 0; i < tutorialFrame.data.size(); ++i)
        worst = std::max(worst, double(std::abs(tutorialFrame.data[i] - keyOnceFrame.data[i])));
    if (!(worst <= 1.5 / 255.0))
        throw Error("bench: the key-once final pass differs from Part 3's by " + std::to_string(worst * 255.0) +
                    " 8-bit steps at " + size.name());
    restoreBloom(targets);
}

// The key, each way once more, read back and compared with the exact mean of the frame.
void measureKeys(const Size& size, Targets& targets, const Programs& programs, t10::ExactKey& exactKey,
                 const t10::Scene& scene, std::vector<KeyResult>& keys) {
    PassClock clock;
    const t10::ImageF frame = t10::readTextureLevel(scene.accumulationTexture(), 0);
    const double exact = t10::ref::meanMappedLogLuminance(frame, true);
    keyMipChain(targets, programs, clock, nullptr);
    clock.finish();
    keys.push_back({"mip", size, readLastLevel(targets.luminance_, targets.lumLevels_ - 1), exact});
    keyComputeChain(targets, programs, exactKey, clock, nullptr);
    clock.finish();
    keys.push_back({"compute", size, double(exactKey.readMean()), exact});
    keyPotChain(targets, programs, clock, nullptr);
    clock.finish();
    const double padded = readLastLevel(targets.pot_, targets.potLevels_ - 1);
    keys.push_back({"pot", size, padded * double(targets.potW_) * double(targets.potH_) / size.pixels(), exact});
}

// Everything measured, and the results by size and chain.
struct Measurements {
    std::vector<Result> results;
    std::vector<KeyResult> keys;
    std::map<std::string, std::map<std::string, const Result*>> bySize; // size -> chain -> result

    const Result& at(const Size& size, const std::string& chain) const { return *bySize.at(size.name()).at(chain); }
    double gpuMedian(const Size& size, const std::string& chain) const { return median(at(size, chain).gpuMs); }
};

// The GL objects every size shares.
struct Bench {
    const Programs& programs;
    t10::ExactKey& exactKey;
    t10::Scene& scene;
    const t10::Camera& camera;
    const t10::FullScreenQuad& quad;
    t10::GlErrorLog& glErrors;
};

void measureSize(const Size& size, const Bench& bench, const NamedChains& chains, int repeats, Measurements& out) {
    std::cout << "measuring " << size.name() << " ..." << std::flush;
    bench.scene.resize(size.width, size.height);
    bench.scene.render(bench.camera);
    glFinish();
    Targets targets(size, bench.scene.accumulationTexture());
    bindUnit(kLuminanceUnit, targets.luminance_);
    restoreBloom(targets);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    bench.quad.bind();
    const std::vector<Result> results = timeChains(size, targets, bench.programs, chains, repeats);
    out.results.insert(out.results.end(), results.begin(), results.end());
    checkKeyOnce(size, targets, bench.programs);
    measureKeys(size, targets, bench.programs, bench.exactKey, bench.scene, out.keys);
    bench.glErrors.pollGetError();
    if (!bench.glErrors.empty()) throw Error("bench: GL error at " + size.name() + ":" + bench.glErrors.describe());
    std::cout << " done\n";
}

// --- Report ---

void chainTimesTable(std::ostream& table, const Options& options, const NamedChains& chains, const Measurements& m) {
    table << "\nChains: tutorial = Part 3 (luminance pass, mip-chain key, 5 pass pairs of 5 taps at half\n"
             "resolution in R11G11B10F, final pass); keyonce = the same, key math once per vertex;\n"
             "lo_full / lo_half = LearnOpenGL-style bloom (RGBA16F bright pass, 10 passes of 9 taps, fixed\n"
             "exposure: no key; add key_mip for a like-for-like figure) at full / half resolution; tap13 =\n"
             "the tutorial's luminance pass and key with a 13-tap downsample / tent upsample chain to 1/64;\n"
             "key_mip / key_compute / key_pot = the key alone (luminance pass + mip chain / compute\n"
             "reduction / padded power-of-two mip chain).\n";
    table << "\nMedian GPU time (GL_TIME_ELAPSED, sum of the chain's passes) over " << options.repeats
          << " interleaved runs, and the ratio to the tutorial's chain\n";
    char cell[64];
    std::snprintf(cell, sizeof cell, "%-10s", "size");
    table << cell;
    for (const auto& named : chains) {
        std::snprintf(cell, sizeof cell, " %20s", named.first.c_str());
        table << cell;
    }
    table << "\n";
    for (const Size& size : options.sizes) {
        const double base = m.gpuMedian(size, "tutorial");
        std::snprintf(cell, sizeof cell, "%-10s", size.name().c_str());
        table << cell;
        for (const auto& named : chains) {
            const double ms = m.gpuMedian(size, named.first);
            std::snprintf(cell, sizeof cell, " %9.2f ms (%5.2fx)", ms, ms / base);
            table << cell;
        }
        table << "\n";
    }
}

std::map<std::string, double> slopeTable(std::ostream& table, const Options& options, const NamedChains& chains,
                                         const Measurements& m) {
    // Slopes from 640x360 up where there are at least two such sizes: below, fixed costs per pass dominate.
    table << "\nlog-log slope of time against pixels (1 = linear in pixels)";
    const bool fromMid = std::count_if(options.sizes.begin(), options.sizes.end(),
                                       [](const Size& s) { return s.pixels() >= 640.0 * 360.0; }) >= 2;
    table << (fromMid ? ", sizes from 640x360 up\n" : ", all sizes\n");
    std::map<std::string, double> slopes;
    char cell[64];
    for (const auto& named : chains) {
        const std::string& name = named.first;
        std::vector<std::pair<double, double>> points;
        for (const Size& size : options.sizes)
            if (!fromMid || size.pixels() >= 640.0 * 360.0) points.emplace_back(size.pixels(), m.gpuMedian(size, name));
        slopes[name] = logLogSlope(points);
        if (std::isnan(slopes[name])) std::snprintf(cell, sizeof cell, "  %-12s n/a (one size)\n", name.c_str());
        else std::snprintf(cell, sizeof cell, "  %-12s %5.2f\n", name.c_str(), slopes[name]);
        table << cell;
    }
    return slopes;
}

void passShareTables(std::ostream& table, const Options& options, const NamedChains& chains, const Measurements& m) {
    // Where the time goes: each pass's share of its chain at the size closest to 1280x720.
    const Size shareSize = *std::min_element(options.sizes.begin(), options.sizes.end(), [](const Size& a, const Size& b) {
        return std::abs(std::log(a.pixels() / 921600.0)) < std::abs(std::log(b.pixels() / 921600.0));
    });
    table << "\nShare of each pass in its chain at " << shareSize.name() << "\n";
    char cell[64];
    for (const auto& named : chains) {
        const Result& r = m.at(shareSize, named.first);
        std::snprintf(cell, sizeof cell, "  %-12s", named.first.c_str());
        table << cell;
        for (const auto& [pass, samples] : r.passMs) {
            std::snprintf(cell, sizeof cell, " %s %.0f%%", pass.c_str(), 100.0 * median(samples) / median(r.gpuMs));
            table << cell << ";";
        }
        table << "\n";
    }
    // The final pass alone: the key math once per vertex against once per pixel.
    auto passMedian = [](const Result& r, const std::string& pass) -> double {
        for (const auto& [name, samples] : r.passMs)
            if (name == pass) return median(samples);
        return NAN;
    };
    table << "\nFinal pass alone, key math once per vertex / once per pixel (keyonce / tutorial):";
    for (const Size& size : options.sizes) {
        std::snprintf(cell, sizeof cell, " %s %.2f;", size.name().c_str(),
                      passMedian(m.at(size, "keyonce"), "final") / passMedian(m.at(size, "tutorial"), "final"));
        table << cell;
    }
    table << "\n";
}

void costAndKeyTables(std::ostream& table, const Options& options, const NamedChains& chains, const Measurements& m) {
    const Size& largest = options.sizes.back();
    table << "\nTexture lookups and bytes per chain at " << largest.name()
          << " (bytes: each source texel read once + each target texel written once)\n";
    char cell[64];
    for (const auto& named : chains) {
        const Cost& c = m.at(largest, named.first).cost;
        const Cost& base = m.at(largest, "tutorial").cost;
        std::snprintf(cell, sizeof cell, "  %-12s %8.1f M lookups (%5.2fx)", named.first.c_str(), c.lookups / 1e6,
                      c.lookups / base.lookups);
        table << cell;
        std::snprintf(cell, sizeof cell, " %8.1f MB (%5.2fx)\n", c.bytes / 1e6, c.bytes / base.bytes);
        table << cell;
    }
    table << "\nScene key Ya against the exact double-precision mean of the same frame (GL_R16 range-mapped\n"
             "log luminance, the tutorial's definition; relative error of Ya)\n";
    std::snprintf(cell, sizeof cell, "%-10s %12s", "size", "exact Ya");
    table << cell;
    for (const char* method : {"mip", "compute", "pot"}) {
        std::snprintf(cell, sizeof cell, " %22s", method);
        table << cell;
    }
    table << "\n";
    for (std::size_t i = 0; i < m.keys.size(); i += 3) {
        std::snprintf(cell, sizeof cell, "%-10s %12.6g", m.keys[i].size.name().c_str(), m.keys[i].exactYa());
        table << cell;
        for (std::size_t j = i; j < i + 3; ++j) {
            std::snprintf(cell, sizeof cell, " %11.6g (%7.3f%%)", m.keys[j].ya(), 100.0 * m.keys[j].relativeError());
            table << cell;
        }
        table << "\n";
    }
}

void writeResultFiles(const Options& options, const NamedChains& chains, const Measurements& m,
                      const std::map<std::string, double>& slopes, const std::string& report) {
    const std::filesystem::path dir(options.outDir);
    std::filesystem::create_directories(dir);
    std::ostringstream csv;
    csv << "size,width,height,pixels,chain,gpu_median_ms,gpu_min_ms,wall_median_ms,ratio_to_tutorial,lookups,bytes\n";
    for (const Result& r : m.results) {
        const double base = m.gpuMedian(r.size, "tutorial");
        csv << r.size.name() << "," << r.size.width << "," << r.size.height << "," << r.size.pixels() << ","
            << r.chain << "," << median(r.gpuMs) << "," << *std::min_element(r.gpuMs.begin(), r.gpuMs.end()) << ","
            << median(r.wallMs) << "," << median(r.gpuMs) / base << "," << r.cost.lookups << "," << r.cost.bytes
            << "\n";
    }
    writeFile(dir / "bench.csv", csv.str());
    std::ostringstream passCsv;
    passCsv << "size,chain,pass,gpu_median_ms,share_of_chain\n";
    for (const Result& r : m.results) {
        for (const auto& [pass, samples] : r.passMs)
            passCsv << r.size.name() << "," << r.chain << "," << pass << "," << median(samples) << ","
                    << median(samples) / median(r.gpuMs) << "\n";
    }
    writeFile(dir / "passes.csv", passCsv.str());
    std::ostringstream keyCsv;
    keyCsv.precision(9);
    keyCsv << "size,width,height,method,mapped,exact_mapped,ya,exact_ya,relative_error\n";
    for (const KeyResult& k : m.keys) {
        keyCsv << k.size.name() << "," << k.size.width << "," << k.size.height << "," << k.method << "," << k.mapped
               << "," << k.exact << "," << k.ya() << "," << k.exactYa() << "," << k.relativeError() << "\n";
    }
    writeFile(dir / "keys.csv", keyCsv.str());
    // One row per size, one column per chain: what tools/bench/plot.gp draws.
    std::ostringstream dat;
    dat << "pixels";
    for (const auto& named : chains) dat << " " << named.first;
    dat << "\n";
    for (const Size& size : options.sizes) {
        dat << size.pixels();
        for (const auto& named : chains) dat << " " << m.gpuMedian(size, named.first);
        dat << "\n";
    }
    writeFile(dir / "times.dat", dat.str());
    std::ostringstream slopeText;
    for (const auto& [name, slope] : slopes) slopeText << name << "," << slope << "\n";
    writeFile(dir / "slopes.csv", "chain,slope\n" + slopeText.str());
    writeFile(dir / "report.txt", report);
}

// The two exact methods must be exact up to their stated rounding, on any driver: a compute
// reduction in float (terms of at most a few hundred values in [0, 1]: 1e-5 of the mapped range
// is a hundred times its rounding), and the padded power-of-two chain (every level an exact 2x2
// average, rounded to GL_R16 again: half a step per level, scaled up by padded / real pixels).
// Returns the number of keys outside their bound.
int checkKeyBounds(const std::vector<KeyResult>& keys) {
    int failures = 0;
    for (const KeyResult& k : keys) {
        double mappedBound = 0.0;
        if (k.method == "compute") mappedBound = 1e-5;
        if (k.method == "pot") {
            const int potW = nextPowerOfTwo(k.size.width), potH = nextPowerOfTwo(k.size.height);
            mappedBound = (0.5 * (fullMipLevels(potW, potH) - 1) / 65535.0 + 1e-5) * double(potW) * double(potH) /
                          k.size.pixels();
        }
        // An error of mappedBound in the mapped mean scales Ya (+ epsilon) by exp(range x mappedBound).
        const double bound = t10::ref::keyFromMapped(mappedBound) / t10::ref::keyFromMapped(0.0) - 1.0;
        if (mappedBound > 0.0 && !(k.relativeError() <= bound)) {
            std::cerr << "t10-bench: FAIL: the " << k.method << " key at " << k.size.name() << " is off by "
                      << 100.0 * k.relativeError() << "% of Ya, more than its bound " << 100.0 * bound << "%\n";
            ++failures;
        }
    }
    return failures;
}

int runBench(const Options& options) {
    t10::ContextOptions contextOptions;
    contextOptions.headless = true;
    contextOptions.width = 64;
    contextOptions.height = 64;
    contextOptions.title = "t10-bench";
#ifdef T10_GL_DEBUG
    contextOptions.debug = true;
#endif
    auto context = t10::Context::create(contextOptions);
    // GL errors are bugs here as everywhere: debug builds get the KHR_debug callback.
    t10::GlErrorLog glErrors;
    glErrors.installDebugCallback();
    const std::string machine = machineDescription(*context);
    std::cout << machine;

    const t10::ShaderManager tutorialShaders({T10_BENCH_TUTORIAL_DIR, T10_COMMON_SHADER_DIR});
    const t10::ShaderManager benchShaders({T10_BENCH_SHADER_DIR, T10_COMMON_SHADER_DIR});
    const Programs programs(tutorialShaders, benchShaders);
    t10::ExactKey exactKey(benchShaders);
    // The built-in scene from its first (default) camera, as every stage renders it.
    const t10::SceneDescription description = t10::loadGltfScene(t10::builtInScenePath());
    t10::Scene scene(tutorialShaders, description);
    const t10::Camera camera(description.cameras.front());
    t10::FullScreenQuad quad;
    const NamedChains chains = makeChains(exactKey);

    const Bench bench{programs, exactKey, scene, camera, quad, glErrors};
    Measurements m;
    for (const Size& size : options.sizes) measureSize(size, bench, chains, options.repeats, m);
    for (const Result& r : m.results) m.bySize[r.size.name()][r.chain] = &r;

    std::ostringstream table;
    chainTimesTable(table, options, chains, m);
    const std::map<std::string, double> slopes = slopeTable(table, options, chains, m);
    passShareTables(table, options, chains, m);
    costAndKeyTables(table, options, chains, m);
    std::cout << table.str();
    writeResultFiles(options, chains, m, slopes, machine + table.str());
    const int failures = checkKeyBounds(m.keys);
    std::cout << "\nwrote " << options.outDir << "/bench.csv, keys.csv, slopes.csv, times.dat, passes.csv, report.txt\n";
    return failures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App cli{"t10-bench: the tutorial's post-process chain against the usual alternatives, and its key's accuracy"};
    Options options;
    std::vector<std::string> sizes = {"320x180", "640x360", "1280x720", "1920x1080", "2560x1440", "3840x2160"};
    cli.add_option("--sizes", sizes, "frame sizes WxH, smallest first")->delimiter(',');
    cli.add_option("--repeats", options.repeats, "timed runs of every chain per size (after one warm-up run)")
        ->check(CLI::Range(1, 100));
    cli.add_option("--out", options.outDir, "folder for bench.csv, keys.csv, slopes.csv and report.txt");
    cli.add_flag("--smoke", options.smoke, "one small size, two runs: checks that everything runs (make test)");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return cli.exit(error) == 0 ? 0 : 2;
    }
    try {
        if (options.smoke) {
            sizes = {"160x90"};
            options.repeats = 2;
        }
        for (const std::string& text : sizes) options.sizes.push_back(parseSize(text));
        std::sort(options.sizes.begin(), options.sizes.end(),
                  [](const Size& a, const Size& b) { return a.pixels() < b.pixels(); });
        return runBench(options);
    } catch (const t10::Error& error) {
        std::cerr << "t10-bench: error: " << error.what() << "\n";
        return error.exitCode();
    } catch (const std::exception& error) {
        std::cerr << "t10-bench: error: " << error.what() << "\n";
        return 1;
    }
}
