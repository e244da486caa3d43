// Linked by t10-grade into every Part 3 submission it builds: records each Gaussian blur pass, which
// --dump only sees after the frame. The submission is compiled with -DrunStage=gradeRunStage, so its
// main() calls gradeRunStage() below without a change to its code. That wraps the stage's GL_Render:
// glad's glDrawElements/glDrawArrays pointers are swapped for wrappers that draw, then, when the
// current program has fragment subroutine uniforms (the blur program: Gauss.frag's SampleOffset) and
// the draw framebuffer's colour attachment is a texture, read that texture level back into
// <dump>/blur_passNN.pfm and describe it in <dump>/blur_passes.txt, one line per pass:
//   <pass> <subroutine name> <texture> <level> <width>x<height>
// Every frame rewrites the files, so after the run they describe the last frame, like --dump.
#include "t10/app.hpp"
#include "t10/gl.hpp"
#include "t10/image_io.hpp"
#include "t10/readback.hpp"
#include "t10/stage.hpp"

#include <cstdio>
#include <stdexcept>
#include <fstream>
#include <sstream>
#include <string>

// The submission's translation unit sees runStage renamed; this one calls the real one.
#undef runStage
namespace t10 {
int runStage(int argc, const char* const* argv, const Stage& stage);
int gradeRunStage(int argc, const char* const* argv, const Stage& stage);
} // namespace t10

namespace {

// One process runs one stage: its render function and glad's originals are held here because GL
// entry points and Stage callbacks are plain function pointers that cannot carry a context.
struct Capture {
    std::string dir; // --dump's folder; empty: nothing is captured
    void (*render)(t10::App&) = nullptr;
    PFNGLDRAWELEMENTSPROC drawElements = nullptr;
    PFNGLDRAWARRAYSPROC drawArrays = nullptr;
    int pass = 0;
    std::ostringstream list;
};

Capture& capture() {
    static Capture state;
    return state;
}

void afterDraw() {
    Capture& c = capture();
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (program == 0 || framebuffer == 0) return;
    GLint subroutineUniforms = 0;
    glGetProgramStageiv(static_cast<GLuint>(program), GL_FRAGMENT_SHADER, GL_ACTIVE_SUBROUTINE_UNIFORMS, &subroutineUniforms);
    if (subroutineUniforms == 0) return;
    GLint type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return;
    GLint texture = 0;
    GLint level = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    // The subroutine the pass ran with: its name says which axis the student meant.
    GLuint index = 0;
    glGetUniformSubroutineuiv(GL_FRAGMENT_SHADER, 0, &index);
    char name[128] = "unknown";
    glGetActiveSubroutineName(static_cast<GLuint>(program), GL_FRAGMENT_SHADER, index, sizeof(name), nullptr, name);
    const t10::ImageF image = t10::readTextureLevel(static_cast<GLuint>(texture), level);
    ++c.pass;
    char file[32];
    std::snprintf(file, sizeof(file), "blur_pass%02d.pfm", c.pass);
    t10::writePfm(c.dir + "/" + file, image);
    c.list << c.pass << " " << name << " " << texture << " " << level << " " << image.width << "x" << image.height << "\n";
}

void GLAD_API_PTR drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    capture().drawElements(mode, count, type, indices);
    afterDraw();
}

void GLAD_API_PTR drawArrays(GLenum mode, GLint first, GLsizei count) {
    capture().drawArrays(mode, first, count);
    afterDraw();
}

void render(t10::App& app) {
    Capture& c = capture();
    // glad is loaded by now; install the wrappers once (a rebuild keeps the same context).
    if (glad_glDrawElements != &drawElements) {
        c.drawElements = glad_glDrawElements;
        c.drawArrays = glad_glDrawArrays;
        glad_glDrawElements = &drawElements;
        glad_glDrawArrays = &drawArrays;
    }
    c.pass = 0;
    c.list.str("");
    c.render(app);
    std::ofstream out(c.dir + "/blur_passes.txt");
    out << c.list.str();
    if (!out) throw std::runtime_error(c.dir + "/blur_passes.txt: cannot write");
}

} // namespace

int t10::gradeRunStage(int argc, const char* const* argv, const Stage& stage) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--dump") capture().dir = argv[i + 1];
    if (capture().dir.empty()) return runStage(argc, argv, stage);
    Stage wrapped = stage; // Stage holds a unique_ptr-free set of pointers and hooks: copyable
    capture().render = stage.render;
    wrapped.render = &render;
    return runStage(argc, argv, wrapped);
}
