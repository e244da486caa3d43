// The pass capture of --capture-passes; see frame_observer.hpp. The draw observation is the
// platform's: draw_observation.cpp (the loader's entry points), draw_observation_web.cpp.
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
        const AttachedLevel target = attachedLevel(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0);
        if (target.texture == 0) return;
        // The subroutine the pass ran with: its name says which axis the student meant.
        GLuint index = 0;
        glGetUniformSubroutineuiv(GL_FRAGMENT_SHADER, 0, &index);
        char name[128] = "unknown";
        glGetActiveSubroutineName(GLuint(program), GL_FRAGMENT_SHADER, index, sizeof(name), nullptr, name);
        const ImageF image = readTextureLevel(target.texture, target.level);
        ++pass_;
        char file[32];
        std::snprintf(file, sizeof(file), "blur_pass%02d.pfm", pass_);
        writePfm((std::filesystem::path(dir_) / file).string(), image);
        list_ << pass_ << " " << name << " " << target.texture << " " << target.level << " " << image.width << "x"
              << image.height << "\n";
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

std::unique_ptr<FrameObserver> makePassCapture(const std::string& dir) { return std::make_unique<PassCapture>(dir); }

} // namespace t10
