// tutorial10_part2_bloom: Tutorial 10, Part 2 "Bloom" (steps 17-25).
//
// Builds on: tutorial10_part1_tonemap (automatic-exposure tone mapping, steps 1-16).
// Adds: bloom. The luminance pass also writes every pixel brighter than 2.95 x the white point into
// g_uiBloom (a second colour attachment); one generated mipmap level halves it, and the final pass
// adds that blurry half-size copy, weighted 0.98, before tone mapping. Each step's code is marked
// "[step N]"; tutorial10_part3_gaussian is this file plus steps 26-36.
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

// [step 21] The bloom texture
GLuint g_uiBloom;
// [/step 21]

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

    // [step 24] Bind texture and generate mipmaps on bloom texture
    glActiveTexture(GL_TEXTURE17);
    glBindTexture(GL_TEXTURE_2D, g_uiBloom);
    glGenerateMipmap(GL_TEXTURE_2D);
    // [/step 24]
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

    // [step 21] Delete the bloom texture
    glDeleteTextures(1, &g_uiBloom);
    // [/step 21]
}

int main(int argc, char** argv)
{
    const t10::Stage stage{T10_STAGE_NAME, "Tutorial 10 stage: " T10_STAGE_NAME, T10_STAGE_SHADER_DIR,
                           GL_Init, GL_Render, GL_Quit};
    return t10::runStage(argc, argv, stage);
}
