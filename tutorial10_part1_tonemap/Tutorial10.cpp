// tutorial10_part1_tonemap: Tutorial 10, Part 1 "Tone Mapping" (steps 1-16).
//
// Builds on: tutorial10_part0_start (the HDR scene in common/ with a pass-through post-process).
// Adds: automatic exposure. A luminance pass writes each pixel's range-mapped log luminance into
// g_uiLuminanceKey, whose mipmap chain averages it down to one texel: the scene key. The final
// post-process pass reads that key and tone maps every pixel with it. Each step's code is marked
// "[step N]"; tutorial10_part2_bloom is this file plus steps 17-25.
#include "t10/app.hpp"

#include <glm/glm.hpp>

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

// [step 12] Post processing frame buffer
GLuint g_uiFBOPostProc;
GLuint g_uiLuminanceKey;
// [/step 12]

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
    glTexStorage2D(GL_TEXTURE_2D, iLevels, GL_R16, g_iWindowWidth, g_iWindowHeight);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // Attach frame buffer attachments
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_uiLuminanceKey, 0);
    t10::requireCompleteFramebuffer(GL_DRAW_FRAMEBUFFER, "g_uiFBOPostProc");

    // Bind luminance texture
    glActiveTexture(GL_TEXTURE16);
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    glActiveTexture(GL_TEXTURE0);
    // [/step 13]

    return true;
}

void GL_RenderPostProcess()
{
    // [step 15] Luminance pass: the log luminance of every pixel, averaged by the mipmap chain
    // Bind initialisation program
    glUseProgram(g_uiPostProcInitProgram);

    // Bind post-process frame buffer
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOPostProc);
    glClear(GL_COLOR_BUFFER_BIT);

    // Draw full screen quad
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);

    // Bind texture and generate mipmaps on luminance key texture. Unit 16 is selected first: the
    // tutorial binds into whichever unit happens to be active, replacing that unit's texture
    glActiveTexture(GL_TEXTURE16);
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    glGenerateMipmap(GL_TEXTURE_2D);
    // [/step 15]

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
}

void GL_Render(t10::App& app)
{
    // Render the scene into the accumulation texture (texture unit 15)
    app.scene().render(app.camera());

    // Post-processing draws full screen quads without depth testing
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glViewport(0, 0, g_iWindowWidth, g_iWindowHeight);
    app.quad().bind();

    GL_RenderPostProcess();
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
}

int main(int argc, char** argv)
{
    const t10::Stage stage{T10_STAGE_NAME, "Tutorial 10 stage: " T10_STAGE_NAME, T10_STAGE_SHADER_DIR,
                           GL_Init, GL_Render, GL_Quit};
    return t10::runStage(argc, argv, stage);
}
