// tutorial10_part0_start: the starting point of Tutorial 10, "Tone Mapping and Bloom".
//
// Builds on: the previous tutorial's renderer, which lives in common/: the normal-mapped,
// parallax-occlusion-mapped room lit by HDR point lights, rendered every frame into a GL_RGBA16F
// accumulation texture that stays bound to texture unit 15.
// Adds: nothing yet. This is "the existing post-processing program" that the tutorial modifies:
// a pass-through that copies the accumulation texture to the default framebuffer, so every value
// above 1.0 simply clips. tutorial10_part1_tonemap is this file plus steps 1-16.
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

    return true;
}

void GL_RenderPostProcess()
{
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
}

int main(int argc, char** argv)
{
    const t10::Stage stage{T10_STAGE_NAME, "Tutorial 10 stage: " T10_STAGE_NAME, T10_STAGE_SHADER_DIR,
                           GL_Init, GL_Render, GL_Quit};
    return t10::runStage(argc, argv, stage);
}
