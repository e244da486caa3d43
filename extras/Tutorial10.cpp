// extras: Tutorial 10, the "Extra" exercises (steps 37-40).
//
// Builds on: tutorial10_part3_gaussian (tone mapping, bloom and its Gaussian blur, steps 1-36).
// With its default settings it renders exactly Part 3's frame.
// Adds, each as a setting with a slider or toggle in a Dear ImGui panel (window mode), a keyboard
// shortcut and a command-line option:
//   37  the white point Yw as a uniform of both post-process shaders (and of the range mapping),
//       and a switch that turns the bloom off to show the tone mapping alone;
//   38  the bloom threshold as a multiple of Yw (0.5-4.0) and the bloom's weight as a uniform;
//   39  the number of blur pass pairs (0-16), each pass timed with GL_TIME_ELAPSED queries (the
//       common --bench N prints the median GPU time of every pass);
//   40  a GL_R16F luminance texture without the range mapping, rebuilt on the fly, with a warning
//       when the key read back from its 1x1 level is NaN or infinite.
// Each step's code is marked "[step N]". The frame loop in common/ calls this file's panel, keys
// and timers (see main()); common/src/imgui_host.cpp holds the Dear ImGui host and widgets, and
// common/include/t10/contract.hpp the tutorial's defaults and the shaders' uniform locations.
#include "t10/app.hpp"

// [step 37] The exercises' panel (Dear ImGui), options (CLI11), keys (GLFW), and the defaults and
// uniform locations they share with the shaders
#include "t10/cli_range.hpp"
#include "t10/contract.hpp"
#include "t10/imgui_host.hpp"
#include "t10/keys.hpp"
#include "t10/views_panel.hpp"

#include <CLI/CLI.hpp>
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <iostream>
#include <string>

namespace loc = t10::contract::extras;
// [/step 37]

// [step 39] GPU pass timers
#include "t10/gpu_timers.hpp"
// [/step 39]

#include <glm/glm.hpp>

// [step 40] std::isfinite for the scene key check, read back a few frames late; the exact key
// (--key exact)
#include "t10/browser_limits.hpp"
#include "t10/exact_key.hpp"
#include "t10/readback.hpp"

#include <cmath>
#include <memory>
#include <optional>
// [/step 40]

using namespace glm;

// Window size (updated by common/ before every GL_Init, including after a resize)
int g_iWindowWidth = 1280;
int g_iWindowHeight = 720;

// Uniform buffer holding the InvResolution block (binding 7)
GLuint g_uiInverseResUBO;

// Post-processing program
GLuint g_uiPostProcProgram;

// [step 1] The luminance (tone mapping initialisation) program
GLuint g_uiPostProcInitProgram;
// [/step 1]

// [step 26] The Gaussian blur program
GLuint g_uiGaussProgram;
// [/step 26]

// [step 12] Post processing frame buffer
GLuint g_uiFBOPostProc;
GLuint g_uiLuminanceKey;
// [/step 12]

// [step 21] The bloom texture
GLuint g_uiBloom;
// [/step 21]

// [step 29] Blur frame buffers and the half resolution intermediate texture
GLuint g_uiFBOBlur;
GLuint g_uiFBOBloom;
GLuint g_uiBlur;
// [/step 29]

// [step 37] The white point Yw: the smallest luminance mapped to pure white (the tutorial's
// constant 0.22), now a uniform of both post-process shaders. g_bBloom off shows the tone map alone.
const float g_fWhitePointMin = 0.05f;
const float g_fWhitePointMax = 2.0f;
float g_fWhitePoint = (float)t10::contract::kWhitePoint;
bool g_bBloom = true;
// [/step 37]

// [step 38] The bloom threshold, a multiple of Yw, and the weight the bloom is added with
const float g_fBloomThresholdMin = 0.5f;
const float g_fBloomThresholdMax = 4.0f;
float g_fBloomThreshold = (float)t10::contract::kBloomThresholdFactor;
const float g_fBloomStrengthMin = 0.0f;
const float g_fBloomStrengthMax = 4.0f;
float g_fBloomStrength = (float)t10::contract::kBloomWeight;
// [/step 38]

// [step 39] The number of blur pass pairs (the tutorial's constant 5) and the time each pass takes
const int g_iBlurPassesMax = 16;
int g_iBlurPasses = t10::contract::kBlurPasses;
// Created, opened and closed every frame, and read back by common/'s frame loop (Stage::timers)
t10::PassTimers g_PassTimers;
// [/step 39]

// [step 40] The luminance texture's format: GL_R16 with the range mapping, or GL_R16F without it
bool g_bLuminanceR16F = false;
int g_iLuminanceLevels = 1;       // levels of g_uiLuminanceKey; the last one is 1x1
t10::TexelReadback g_KeyReadback; // copies that level without waiting: the key is a few frames old
float g_fSceneKey = 0.0f;         // Ya, read back from that level
bool g_bSceneKeyValid = true;     // false while the read-back key is NaN or infinite
bool g_bSceneKeyReported = false; // the warning goes to stderr once per run
// --key exact: replace the mip chain's 1x1 level by the exact mean of level 0 (common/exact_key.hpp),
// since at odd sizes glGenerateMipmap's filter may skip rows and columns
bool g_bExactKey = false;
std::unique_ptr<t10::ExactKey> g_pExactKey;
// [/step 40]

// [step 37] The window's panel and keyboard shortcuts
bool g_bShowPanel = true;
t10::KeyEdges g_Keys;
// [/step 37]

bool GL_Init(t10::App& app)
{
    g_iWindowWidth = app.width();
    g_iWindowHeight = app.height();

    // Create the inverse resolution UBO and bind it to binding 7
    glGenBuffers(1, &g_uiInverseResUBO);
    glBindBufferBase(GL_UNIFORM_BUFFER, 7, g_uiInverseResUBO);
    vec2 v2InverseRes = 1.0f / vec2((float)g_iWindowWidth, (float)g_iWindowHeight);
    glBufferData(GL_UNIFORM_BUFFER, sizeof(vec2), &v2InverseRes, GL_STATIC_DRAW);

    // Load the post-processing program (full screen quad + pass-through)
    g_uiPostProcProgram = app.shaders().createProgram({"FullScreenQuad.vert", "PostProcess.frag"});

    // [step 11] Load the luminance program: the same full screen quad vertex shader, new fragment shader
    g_uiPostProcInitProgram = app.shaders().createProgram({"FullScreenQuad.vert", "PostProcessInit.frag"});
    // [/step 11]

    // [step 28] Load the Gaussian blur program: the same full screen quad vertex shader
    g_uiGaussProgram = app.shaders().createProgram({"FullScreenQuad.vert", "Gauss.frag"});
    // [/step 28]

    // [step 13] Create post-process frame buffer
    glGenFramebuffers(1, &g_uiFBOPostProc);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOPostProc);

    // Generate attachment textures
    glGenTextures(1, &g_uiLuminanceKey);

    // Setup luminance attachment
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    // The chain down to 1x1 has floor(log2(max)) + 1 levels: the tutorial's ceil(log2(max)) is one
    // level short for power-of-two sizes, which leaves a 2x1 (not 1x1) smallest level
    int iLevels = (int)floorf(log2f((float)max(g_iWindowWidth, g_iWindowHeight))) + 1;
    // [step 40] GL_R16F holds log luminance as it is; GL_R16 needs it range mapped to [0, 1]
    glTexStorage2D(GL_TEXTURE_2D, iLevels, g_bLuminanceR16F ? GL_R16F : GL_R16, g_iWindowWidth, g_iWindowHeight);
    g_iLuminanceLevels = iLevels;
    if (g_bExactKey && !g_pExactKey) g_pExactKey = std::make_unique<t10::ExactKey>(app.shaders());
    // [/step 40]
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // Attach frame buffer attachments
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_uiLuminanceKey, 0);

    // [step 21] Generate the bloom texture
    glGenTextures(1, &g_uiBloom);
    // [/step 21]

    // [step 22] Setup bloom attachment: two levels, the second is the half-size copy that is read
    glBindTexture(GL_TEXTURE_2D, g_uiBloom);
    iLevels = 2;
    glTexStorage2D(GL_TEXTURE_2D, iLevels, GL_R11F_G11F_B10F, g_iWindowWidth, g_iWindowHeight);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, iLevels - 1);
    // [/step 22]

    // [step 23] Attach frame buffer attachments
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, g_uiBloom, 0);

    // Enable frame buffer attachments
    GLenum uiDrawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, uiDrawBuffers);
    // [/step 23]

    t10::requireCompleteFramebuffer(GL_DRAW_FRAMEBUFFER, "g_uiFBOPostProc");

    // Bind luminance texture
    glActiveTexture(GL_TEXTURE16);
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    glActiveTexture(GL_TEXTURE0);
    // [/step 13]

    // [step 30] Create blur frame buffers
    glGenFramebuffers(1, &g_uiFBOBlur);
    glGenFramebuffers(1, &g_uiFBOBloom);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBlur);

    // Create blur texture at half resolution. Integer division rounds odd sizes down, exactly as
    // level 1 of the bloom texture does (common/ keeps the window at least 2x2, so never 0)
    glGenTextures(1, &g_uiBlur);
    glBindTexture(GL_TEXTURE_2D, g_uiBlur);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_R11F_G11F_B10F, g_iWindowWidth / 2, g_iWindowHeight / 2);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // Attach frame buffer attachments
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_uiBlur, 0);
    t10::requireCompleteFramebuffer(GL_DRAW_FRAMEBUFFER, "g_uiFBOBlur");

    // Attach second frame buffer to bloom second mipmap level
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBloom);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_uiBloom, 1);
    t10::requireCompleteFramebuffer(GL_DRAW_FRAMEBUFFER, "g_uiFBOBloom");
    // [/step 30]

    return true;
}

void GL_RenderPostProcess()
{
    // [step 37] The white point (both programs) and the bloom switch
    glProgramUniform1f(g_uiPostProcInitProgram, loc::kWhitePointLocation, g_fWhitePoint);
    glProgramUniform1f(g_uiPostProcProgram, loc::kWhitePointLocation, g_fWhitePoint);
    glProgramUniform1i(g_uiPostProcProgram, loc::kBloomSwitchLocation, g_bBloom);
    // [/step 37]
    // [step 38] The bloom threshold (a multiple of Yw) and the bloom's weight
    glProgramUniform1f(g_uiPostProcInitProgram, loc::kBloomThresholdLocation, g_fBloomThreshold);
    glProgramUniform1f(g_uiPostProcProgram, loc::kBloomStrengthLocation, g_fBloomStrength);
    // [/step 38]
    // [step 40] The range mapping only suits the integer GL_R16 texture
    glProgramUniform1i(g_uiPostProcInitProgram, loc::kRangeMappingLocation, !g_bLuminanceR16F);
    glProgramUniform1i(g_uiPostProcProgram, loc::kRangeMappingLocation, !g_bLuminanceR16F);
    // [/step 40]

    // [step 39] Time the luminance pass
    g_PassTimers.begin("luminance");
    // [/step 39]
    // [step 15] Luminance pass: the log luminance of every pixel, averaged by the mipmap chain
    // Bind initialisation program
    glUseProgram(g_uiPostProcInitProgram);

    // Bind post-process frame buffer
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOPostProc);
    glClear(GL_COLOR_BUFFER_BIT);

    // Draw full screen quad
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

    // [step 39] Time the mipmap chain
    g_PassTimers.begin("mip chain");
    // [/step 39]
    // Bind texture and generate mipmaps on luminance key texture. Unit 16 is selected first: the
    // tutorial binds into whichever unit happens to be active, replacing that unit's texture
    glActiveTexture(GL_TEXTURE16);
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    glGenerateMipmap(GL_TEXTURE_2D);
    // [step 40] --key exact: the exact mean of level 0 replaces the mip chain's 1x1 level
    if (g_pExactKey) g_pExactKey->store(g_uiLuminanceKey, g_iWindowWidth, g_iWindowHeight, g_iLuminanceLevels - 1);
    // [/step 40]
    // [/step 15]

    // [step 24] Bind texture and generate mipmaps on bloom texture
    glActiveTexture(GL_TEXTURE17);
    glBindTexture(GL_TEXTURE_2D, g_uiBloom);
    // [step 31] Instead of generating level 1, clamp reads to level 0 (written by the luminance
    // pass) until the blur has written level 1
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    // [/step 31]
    // [/step 24]

    // [step 39] Blur only with the bloom on and at least one pass; with none, the bloom is read
    // unblurred from level 0 (step 31)
    if (g_bBloom && g_iBlurPasses > 0) {
        // [/step 39]
        // [step 32] Blur passes at half resolution; first horizontally from bloom level 0 into g_uiBlur
        // Half viewport
        glViewport(0, 0, g_iWindowWidth / 2, g_iWindowHeight / 2);
        vec2 v2InverseRes = 1.0f / vec2((float)(g_iWindowWidth / 2), (float)(g_iWindowHeight / 2));
        glBindBuffer(GL_UNIFORM_BUFFER, g_uiInverseResUBO);
        glBufferData(GL_UNIFORM_BUFFER, sizeof(vec2), &v2InverseRes, GL_STATIC_DRAW);

        // Bind blur frame buffer and program
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBlur);
        glUseProgram(g_uiGaussProgram);

        // [step 39] Time the first blur pass (horizontal + vertical)
        g_PassTimers.begin("blur 1");
        // [/step 39]
        // Perform horizontal blur
        GLuint uiSubRoutines[2] = {0, 1};
        glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[0]);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);
        // [/step 32]

        // [step 33] Vertical blur from g_uiBlur into bloom level 1. Unit 17 (still active) now holds
        // g_uiBlur, so no pass samples the level it renders into
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBloom);
        glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[1]);
        glBindTexture(GL_TEXTURE_2D, g_uiBlur);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

        // Bind second blur mipmap level as texture input
        glBindTexture(GL_TEXTURE_2D, g_uiBloom);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
        // [/step 33]

        // [step 34] Repeat the pair: each pass reads bloom level 1 (or g_uiBlur) and writes the other
        // [step 39] The pass count is a setting (the tutorial's constant 5)
        const int iBlurPasses = g_iBlurPasses;
        // [/step 39]
        for (int i = 1; i < iBlurPasses; i++) {
            // [step 39] Time each pass pair on its own
            g_PassTimers.begin("blur " + std::to_string(i + 1));
            // [/step 39]
            // Perform horizontal blur
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBlur);
            glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[0]);
            glClear(GL_COLOR_BUFFER_BIT);
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

            // Perform vertical blur
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOBloom);
            glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[1]);
            glBindTexture(GL_TEXTURE_2D, g_uiBlur);
            glClear(GL_COLOR_BUFFER_BIT);
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

            // Rebind bloom texture
            glBindTexture(GL_TEXTURE_2D, g_uiBloom);
        }
        // [/step 34]

        // [step 35] Reset viewport
        glViewport(0, 0, g_iWindowWidth, g_iWindowHeight);
        v2InverseRes = 1.0f / vec2((float)g_iWindowWidth, (float)g_iWindowHeight);
        glBufferData(GL_UNIFORM_BUFFER, sizeof(vec2), &v2InverseRes, GL_STATIC_DRAW);
        // [/step 35]
        // [step 39] End of the blur block
    }
    // [/step 39]

    // [step 39] Time the final pass
    g_PassTimers.begin("final");
    // [/step 39]
    // Final pass: draw the accumulation texture into the default frame buffer
    // Bind default frame buffer
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glClear(GL_COLOR_BUFFER_BIT);

    // Bind final program
    glUseProgram(g_uiPostProcProgram);

    // Draw full screen quad
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

    // Enable depth tests again
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);

    // [step 39] The last pass ends here
    g_PassTimers.end();
    // [/step 39]
}

// [step 40] Read the scene key back from the 1x1 level of the luminance texture. With GL_R16F,
// hardware whose glGenerateMipmap mishandles float formats leaves NaN (or infinity) there, and
// every pixel of the frame turns black: say so instead of failing silently. The copy is queued
// every frame and read once the GPU has made it, so no frame waits for it.
void GL_CheckSceneKey()
{
    g_KeyReadback.request(g_uiLuminanceKey, g_iLuminanceLevels - 1);
    const std::optional<float> fKey = g_KeyReadback.poll();
    if (!fKey) return;
    float fYa = *fKey;
    if (!g_bLuminanceR16F) {
        // Undo the range mapping, as the post-process shader does
        const float fEpsilon = (float)t10::contract::kEpsilon;
        fYa = (fYa * (log(g_fWhitePoint) - log(fEpsilon))) + log(fEpsilon);
    }
    g_bSceneKeyValid = std::isfinite(fYa);
    g_fSceneKey = g_bSceneKeyValid ? exp(fYa) : fYa;
    if (!g_bSceneKeyValid && !g_bSceneKeyReported) {
        g_bSceneKeyReported = true;
        std::cerr << T10_STAGE_NAME ": warning: the scene key read back from the 1x1 level of the "
                  << (g_bLuminanceR16F ? "GL_R16F" : "GL_R16") << " luminance texture is "
                  << (std::isnan(fYa) ? "NaN" : "infinite")
                  << ", so the tone map turns the frame black. glGenerateMipmap on this GPU does not average a "
                     "float texture correctly (or the scene holds a non-finite value); use --luminance-format r16 "
                     "(key L in the window).\n";
    }
}
// [/step 40]

// [step 37] The settings panel (window mode): one widget per setting, each with its shortcut
void GL_RenderPanel(t10::App& app)
{
    if (!g_bShowPanel) return;
    t10::ui::beginPanel("Tutorial 10 extras");
    ImGui::Text("frame %.2f ms (%.0f fps)", app.frameTimeMs(), app.frameTimeMs() > 0.0 ? 1000.0 / app.frameTimeMs() : 0.0);

    t10::ui::heading("Step 37: white point");
    t10::ui::sliderFloat("Yw", &g_fWhitePoint, g_fWhitePointMin, g_fWhitePointMax, "Up/Down", "%.3f", true);
    t10::ui::checkbox("bloom", &g_bBloom, "B");

    // [step 38] Threshold and strength
    t10::ui::heading("Step 38: bloom threshold and strength");
    t10::ui::sliderFloat("threshold x Yw", &g_fBloomThreshold, g_fBloomThresholdMin, g_fBloomThresholdMax, "[ ]", "%.2f");
    ImGui::Text("  blooms where luminance >= %.3f", g_fBloomThreshold * g_fWhitePoint);
    t10::ui::sliderFloat("strength", &g_fBloomStrength, g_fBloomStrengthMin, g_fBloomStrengthMax, "- =", "%.2f");
    // [/step 38]

    // [step 39] Pass count and the GPU time of each pass (a few frames old: the queries are not waited for)
    t10::ui::heading("Step 39: blur passes");
    t10::ui::sliderInt("passes", &g_iBlurPasses, 0, g_iBlurPassesMax, "PgUp/PgDn, 0-9");
    double dPostMs = 0.0;
    for (const t10::PassTime& pass : g_PassTimers.latest()) {
        ImGui::Text("  %-12s %8.3f ms", pass.name.c_str(), pass.ms);
        if (pass.name != "scene") dPostMs += pass.ms;
    }
    ImGui::Text("  %-12s %8.3f ms", "post-process", dPostMs);
    // [/step 39]

    // [step 40] Luminance format and the key read back
    t10::ui::heading("Step 40: luminance format");
    if (t10::ui::checkbox("GL_R16F, no range mapping", &g_bLuminanceR16F, "L")) app.requestRebuild();
    ImGui::Text("  key Ya = %.5g", g_fSceneKey);
    if (!g_bSceneKeyValid) {
        t10::ui::warning(std::string("The key read back is ") + (std::isnan(g_fSceneKey) ? "NaN" : "infinite") +
                      ": glGenerateMipmap on this GPU breaks float textures, so the frame is black. "
                      "Press L for GL_R16.");
    }
    // [/step 40]

    t10::ui::heading("Views (V, Shift+V; T: thumbnails)");
    t10::ui::viewList(app.views());

    ImGui::Spacing();
    ImGui::TextDisabled("R resets every setting, H hides this panel");
    t10::ui::endPanel();
}

// Edge-triggered shortcuts (WASD, Q/E, Shift, the mouse and Esc belong to common/'s camera)
void GL_HandleKeys(t10::App& app)
{
    GLFWwindow* pWindow = app.context().window();
    if (g_Keys.pressed(pWindow, GLFW_KEY_H)) g_bShowPanel = !g_bShowPanel;
    if (g_Keys.pressed(pWindow, GLFW_KEY_UP)) g_fWhitePoint = min(g_fWhitePoint * 1.25f, g_fWhitePointMax);
    if (g_Keys.pressed(pWindow, GLFW_KEY_DOWN)) g_fWhitePoint = max(g_fWhitePoint / 1.25f, g_fWhitePointMin);
    if (g_Keys.pressed(pWindow, GLFW_KEY_B)) g_bBloom = !g_bBloom;
    // [step 38] Threshold and strength keys
    if (g_Keys.pressed(pWindow, GLFW_KEY_RIGHT_BRACKET))
        g_fBloomThreshold = min(g_fBloomThreshold + 0.25f, g_fBloomThresholdMax);
    if (g_Keys.pressed(pWindow, GLFW_KEY_LEFT_BRACKET))
        g_fBloomThreshold = max(g_fBloomThreshold - 0.25f, g_fBloomThresholdMin);
    if (g_Keys.pressed(pWindow, GLFW_KEY_EQUAL)) g_fBloomStrength = min(g_fBloomStrength + 0.25f, g_fBloomStrengthMax);
    if (g_Keys.pressed(pWindow, GLFW_KEY_MINUS)) g_fBloomStrength = max(g_fBloomStrength - 0.25f, g_fBloomStrengthMin);
    // [/step 38]
    // [step 39] Pass count keys
    if (g_Keys.pressed(pWindow, GLFW_KEY_PAGE_UP)) g_iBlurPasses = min(g_iBlurPasses + 1, g_iBlurPassesMax);
    if (g_Keys.pressed(pWindow, GLFW_KEY_PAGE_DOWN)) g_iBlurPasses = max(g_iBlurPasses - 1, 0);
    for (int iDigit = 0; iDigit <= 9; iDigit++) {
        if (g_Keys.pressed(pWindow, GLFW_KEY_0 + iDigit)) g_iBlurPasses = iDigit;
    }
    // [/step 39]
    // [step 40] Luminance format key
    if (g_Keys.pressed(pWindow, GLFW_KEY_L)) {
        g_bLuminanceR16F = !g_bLuminanceR16F;
        app.requestRebuild();
    }
    // [/step 40]
    if (g_Keys.pressed(pWindow, GLFW_KEY_R)) {
        g_fWhitePoint = (float)t10::contract::kWhitePoint;
        g_bBloom = true;
        g_fBloomThreshold = (float)t10::contract::kBloomThresholdFactor;
        g_fBloomStrength = (float)t10::contract::kBloomWeight;
        g_iBlurPasses = t10::contract::kBlurPasses;
        if (g_bLuminanceR16F) app.requestRebuild();
        g_bLuminanceR16F = false;
    }
}
// [/step 37]

// [step 39] The heading of a --bench table: the settings it ran with
std::string GL_BenchSettings()
{
    return std::to_string(g_iBlurPasses) + " blur passes, bloom " + (g_bBloom ? "on" : "off") + ", " +
           (g_bLuminanceR16F ? "GL_R16F" : "GL_R16") + " luminance";
}
// [/step 39]

void GL_Render(t10::App& app)
{
    // [step 39] Time the scene (common/ opens the timers' frame before GL_Render and closes it after)
    g_PassTimers.begin("scene");
    // [/step 39]

    // Render the scene into the accumulation texture (texture unit 15)
    app.scene().render(app.camera());

    // Post-processing draws full screen quads without depth testing
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glViewport(0, 0, g_iWindowWidth, g_iWindowHeight);
    app.quad().bind();

    GL_RenderPostProcess();

    // [step 40] Check the scene key
    GL_CheckSceneKey();
    // [/step 40]
}

void GL_Quit()
{
    // Delete the post-processing objects
    glDeleteProgram(g_uiPostProcProgram);
    glDeleteBuffers(1, &g_uiInverseResUBO);

    // [step 14] Delete the tone mapping objects
    glDeleteFramebuffers(1, &g_uiFBOPostProc);
    glDeleteTextures(1, &g_uiLuminanceKey);
    glDeleteProgram(g_uiPostProcInitProgram);
    // [/step 14]

    // [step 21] Delete the bloom texture
    glDeleteTextures(1, &g_uiBloom);
    // [/step 21]

    // [step 30] Delete the blur objects
    glDeleteFramebuffers(1, &g_uiFBOBlur);
    glDeleteFramebuffers(1, &g_uiFBOBloom);
    glDeleteTextures(1, &g_uiBlur);
    glDeleteProgram(g_uiGaussProgram);
    // [/step 30]

    // [step 40] Delete the key's read-back buffers (with their pending copies), and the exact key's
    // program and buffers while the context is current
    g_KeyReadback.destroy();
    g_pExactKey.reset();
    // [/step 40]
}

// [step 37] The command-line options of the exercises (out-of-range values exit 2 with the range),
// and the shortcuts for --help
void GL_AddOptions(CLI::App& cli)
{
    cli.add_option("--white-point", g_fWhitePoint, "Step 37: the white point Yw, the smallest luminance shown as pure "
                                                   "white")
        ->capture_default_str()
        ->check(t10::inRange(g_fWhitePointMin, g_fWhitePointMax));
    // A negated flag: --no-bloom turns the bloom off, --no-bloom=false back on (the web page's
    // checkbox, which sets options one by one)
    cli.add_flag("!--no-bloom", g_bBloom, "Step 37: turn the bloom off (the tone mapping alone)");
    // [step 38] Threshold and strength options
    cli.add_option("--bloom-threshold", g_fBloomThreshold, "Step 38: bloom where the luminance reaches this multiple "
                                                           "of Yw")
        ->capture_default_str()
        ->check(t10::inRange(g_fBloomThresholdMin, g_fBloomThresholdMax));
    cli.add_option("--bloom-strength", g_fBloomStrength, "Step 38: the weight the bloom is added with")
        ->capture_default_str()
        ->check(t10::inRange(g_fBloomStrengthMin, g_fBloomStrengthMax));
    // [/step 38]
    // [step 39] Pass count option (--bench and --bench-csv are common/'s)
    cli.add_option("--blur-passes", g_iBlurPasses, "Step 39: horizontal + vertical blur pass pairs")
        ->capture_default_str()
        ->check(t10::inRange(0, g_iBlurPassesMax, true));
    // [/step 39]
    // [step 40] Luminance format option
    cli.add_option_function<std::string>(
           "--luminance-format", [](const std::string& strFormat) { g_bLuminanceR16F = strFormat == "r16f"; },
           "Step 40: r16 (GL_R16 with range mapping, the default) or r16f (GL_R16F without)")
        ->check(CLI::IsMember({"r16", "r16f"}));
    cli.add_option_function<std::string>(
           "--key", [](const std::string& strKey) { g_bExactKey = strKey == "exact"; },
           "Step 40: mip (the 1x1 level of the mip chain, the default) or exact (the mean of every pixel, "
           "computed on the GPU; the mip chain is inexact at odd sizes)")
        ->check(CLI::IsMember({"mip", "exact"}))
        // a compute reduction: the browser build refuses it by name (and offers no control for it)
        ->check(t10::refusedInBrowser("exact", "WebGL 2 has no compute shaders, which the exact key is"));
    // [/step 40]
    cli.footer("Keys in the window (besides WASD, Q/E, Shift, the right mouse button, scroll and Esc):\n"
               "  Up / Down          white point Yw x1.25 / /1.25 (step 37)\n"
               "  B                  bloom on / off (step 37)\n"
               "  ] / [              bloom threshold +0.25 / -0.25 x Yw (step 38)\n"
               "  = / -              bloom strength +0.25 / -0.25 (step 38)\n"
               "  PageUp / PageDown  blur passes +1 / -1; 0-9 sets them (step 39)\n"
               "  L                  luminance texture GL_R16 / GL_R16F (step 40)\n"
               "  R                  reset every setting\n"
               "  H                  hide or show the panel\n"
               "  V / Shift+V, T     next / previous view of the chain, thumbnails (common/, as --view)");
}
// [/step 37]

int main(int argc, char** argv)
{
    // [step 37] The exercises add their options, shortcuts and panel (drawn with Dear ImGui)
    t10::Stage stage{T10_STAGE_NAME, "Tutorial 10 stage: " T10_STAGE_NAME " (Part 3 and the exercises, steps 37-40)",
                     T10_STAGE_SHADER_DIR, GL_Init, GL_Render, GL_Quit, GL_AddOptions};
    stage.makeUi = t10::ui::makeImGuiHost;
    stage.keys = GL_HandleKeys;
    stage.panel = GL_RenderPanel;
    // [/step 37]
    // [step 39] The pass timers, for the panel and --bench
    stage.timers = &g_PassTimers;
    stage.benchSettings = GL_BenchSettings;
    // [/step 39]
    return t10::runStage(argc, argv, stage);
}
