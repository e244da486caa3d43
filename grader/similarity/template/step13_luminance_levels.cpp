// Tutorial 10 step 13 as the tutorial prints it: ceil(log2(max)) levels, one short for power-of-two
// sizes (the reference uses floor(log2(max)) + 1). Template for the similarity check; never built.
void tutorialStep13()
{
    // Create post-process frame buffer
    glGenFramebuffers(1, &g_uiFBOPostProc);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g_uiFBOPostProc);

    // Generate attachment textures
    glGenTextures(1, &g_uiLuminanceKey);

    // Setup luminance attachment
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    int iLevels = (int)ceilf(log2f((float)max(g_iWindowWidth, g_iWindowHeight)));
    glTexStorage2D(GL_TEXTURE_2D, iLevels, GL_R16, g_iWindowWidth, g_iWindowHeight);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    // Attach frame buffer attachments
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_uiLuminanceKey, 0);

    // Bind luminance texture
    glActiveTexture(GL_TEXTURE16);
    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);
    glActiveTexture(GL_TEXTURE0);
}
