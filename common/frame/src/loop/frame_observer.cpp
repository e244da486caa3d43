// The capture hook's draw observation and the pass capture of --capture-passes; see frame_observer.hpp.
#include "t10/frame_observer.hpp"

#include "t10/error.hpp"
#include "t10/gl.hpp"
#include "t10/image_io.hpp"
#include "t10/readback.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace t10 {

namespace {

#ifndef __EMSCRIPTEN__ // the browser build has no loader whose entry points could be swapped
// The loader's entry points while a DrawObservation is alive, and whom to tell. GL entry points are
// plain function pointers that carry no context, so this is the one per-process slot they can reach.
struct ObservedDraws {
    FrameObserver* observer = nullptr;
    PFNGLDRAWELEMENTSPROC drawElements = nullptr;
    PFNGLDRAWARRAYSPROC drawArrays = nullptr;
};

ObservedDraws& observedDraws() {
    static ObservedDraws slot;
    return slot;
}

void GLAD_API_PTR observedDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    ObservedDraws& slot = observedDraws();
    slot.drawElements(mode, count, type, indices);
    slot.observer->afterDraw();
}

void GLAD_API_PTR observedDrawArrays(GLenum mode, GLint first, GLsizei count) {
    ObservedDraws& slot = observedDraws();
    slot.drawArrays(mode, first, count);
    slot.observer->afterDraw();
}
#endif

class PassCapture final : public FrameObserver {
public:
    explicit PassCapture(std::string dir) : dir_(std::move(dir)) {
        std::error_code error;
        std::filesystem::create_directories(dir_, error);
        if (error) throw Error("--capture-passes " + dir_ + ": cannot create folder: " + error.message());
    }

    void beginRender() override {
        pass_ = 0;
        list_.str("");
    }

    void afterDraw() override {
        GLint program = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        GLint framebuffer = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
        if (program == 0 || framebuffer == 0) return;
        GLint subroutineUniforms = 0;
        glGetProgramStageiv(GLuint(program), GL_FRAGMENT_SHADER, GL_ACTIVE_SUBROUTINE_UNIFORMS, &subroutineUniforms);
        if (subroutineUniforms == 0) return;
        GLint type = GL_NONE;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type != GL_TEXTURE) return;
        GLint texture = 0;
        GLint level = 0;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
        // The subroutine the pass ran with: its name says which axis the student meant.
        GLuint index = 0;
        glGetUniformSubroutineuiv(GL_FRAGMENT_SHADER, 0, &index);
        char name[128] = "unknown";
        glGetActiveSubroutineName(GLuint(program), GL_FRAGMENT_SHADER, index, sizeof(name), nullptr, name);
        const ImageF image = readTextureLevel(GLuint(texture), level);
        ++pass_;
        char file[32];
        std::snprintf(file, sizeof(file), "blur_pass%02d.pfm", pass_);
        writePfm((std::filesystem::path(dir_) / file).string(), image);
        list_ << pass_ << " " << name << " " << texture << " " << level << " " << image.width << "x" << image.height
              << "\n";
    }

    void endRender() override {
        const std::string path = (std::filesystem::path(dir_) / "blur_passes.txt").string();
        std::ofstream out(path);
        out << list_.str();
        if (!out) throw Error("--capture-passes: " + path + ": cannot write");
    }

private:
    std::string dir_;
    int pass_ = 0;
    std::ostringstream list_;
};

} // namespace

#ifdef __EMSCRIPTEN__
DrawObservation::DrawObservation(FrameObserver&) {
    throw Error("--capture-passes is not available in the web build (WebGL 2's calls cannot be observed)");
}
DrawObservation::~DrawObservation() = default;
#else
DrawObservation::DrawObservation(FrameObserver& observer) {
    ObservedDraws& slot = observedDraws();
    if (slot.observer != nullptr) throw Error("a draw observation is already installed (one at a time)");
    slot.observer = &observer;
    slot.drawElements = glad_glDrawElements;
    slot.drawArrays = glad_glDrawArrays;
    glad_glDrawElements = &observedDrawElements;
    glad_glDrawArrays = &observedDrawArrays;
}

DrawObservation::~DrawObservation() {
    ObservedDraws& slot = observedDraws();
    glad_glDrawElements = slot.drawElements;
    glad_glDrawArrays = slot.drawArrays;
    slot = ObservedDraws{};
}
#endif

std::unique_ptr<FrameObserver> makePassCapture(const std::string& dir) { return std::make_unique<PassCapture>(dir); }

} // namespace t10
