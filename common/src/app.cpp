// The shared frame loop: context, scene, stage callbacks, input, resizes, GL error checks and the
// output files (--output, --exr, --dump).
#include "t10/app.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <sstream>

namespace t10 {

namespace {

constexpr float kMoveSpeed = 3.0f;      // metres per second
constexpr float kFastMultiplier = 4.0f; // with Shift held
constexpr double kTitleInterval = 0.5;  // seconds between title updates

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text != nullptr ? text : "?";
}

void createParentDirectory(const std::string& file) {
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    std::error_code error;
    if (!parent.empty()) std::filesystem::create_directories(parent, error);
    if (error) throw Error(file + ": cannot create folder " + parent.string() + ": " + error.message());
}

} // namespace

App::App(const Stage& stage, const Options& options, Context& context)
    : stage_(stage), options_(options), context_(context),
      shaders_([&] {
          std::vector<std::filesystem::path> dirs;
          if (!options.shaderDir.empty()) dirs.emplace_back(options.shaderDir);
          dirs.emplace_back(stage.shaderDir);
          dirs.emplace_back(T10_COMMON_SHADER_DIR);
          return dirs;
      }()),
      camera_(*findCameraPreset(options.camera)), glErrors_(std::make_unique<GlErrorLog>()) {
    glErrors_->installDebugCallback();
    if (options_.verbose) {
        std::cout << "backend:  " << context_.description() << "\n"
                  << "vendor:   " << glString(GL_VENDOR) << "\n"
                  << "renderer: " << glString(GL_RENDERER) << "\n"
                  << "version:  " << glString(GL_VERSION) << "\n";
    }
    quad_ = std::make_unique<FullScreenQuad>();
    views_ = std::make_unique<ViewService>(shaders_, *findView(options_.view));
    views_->showThumbnails(options_.thumbnails);
    scene_ = std::make_unique<Scene>(shaders_, T10_ASSET_DIR);
    context_.framebufferSize(width_, height_);
    if (!options_.input.empty()) {
        ImageF image = readExr(options_.input);
        if (options_.sizeGiven && (image.width != options_.width || image.height != options_.height)) {
            throw UsageError("--input " + options_.input + " is " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " but --size asks for " + std::to_string(options_.width) +
                             "x" + std::to_string(options_.height));
        }
        if (image.width != width_ || image.height != height_) {
            context_.requestSize(image.width, image.height);
            context_.framebufferSize(width_, height_);
        }
        scene_->setInputImage(std::move(image));
    }
    if (context_.isWindow()) {
        glfwSetWindowUserPointer(context_.window(), this);
        glfwSetScrollCallback(context_.window(), [](GLFWwindow* window, double, double dy) {
            static_cast<App*>(glfwGetWindowUserPointer(window))->camera_.zoom(static_cast<float>(dy));
        });
        glfwSetKeyCallback(context_.window(), [](GLFWwindow* window, int key, int, int action, int mods) {
            if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
            ViewService& views = *static_cast<App*>(glfwGetWindowUserPointer(window))->views_;
            if (key == GLFW_KEY_V && action == GLFW_PRESS) views.cycle((mods & GLFW_MOD_SHIFT) ? -1 : 1);
            if (key == GLFW_KEY_T && action == GLFW_PRESS) views.showThumbnails(!views.thumbnails());
        });
        if (!options_.input.empty()) glfwSetWindowAttrib(context_.window(), GLFW_RESIZABLE, GLFW_FALSE);
    }
}

App::~App() {
    if (stageReady_) stage_.quit();
}

void App::resize(int width, int height) {
    if (stageReady_) {
        stage_.quit();
        stageReady_ = false;
    }
    // A window manager may ignore the size limits: anything below 2x2 is treated like a minimised
    // window (nothing is rendered until it grows again).
    if (width < kMinFramebufferSide || height < kMinFramebufferSide) width = height = 0;
    width_ = width;
    height_ = height;
    if (width == 0 || height == 0) return; // minimised: nothing to render until it comes back
    if (!options_.input.empty() && (width != scene_->width() || height != scene_->height()) && scene_->width() != 0) {
        throw Error("--input " + options_.input + ": the framebuffer cannot be resized while an input image is shown");
    }
    scene_->resize(width, height);
    // Every size-dependent object of the stage is rebuilt exactly as at start-up.
    if (!stage_.init(*this)) throw Error(std::string(stage_.name) + ": GL_Init failed");
    stageReady_ = true;
}

void App::handleInput(double seconds) {
    GLFWwindow* window = context_.window();
    if (window == nullptr) return;
    glm::vec3 move(0.0f);
    if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move.z += 1.0f;
    if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move.z -= 1.0f;
    if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move.x += 1.0f;
    if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move.x -= 1.0f;
    if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
    if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
    float speed = kMoveSpeed * static_cast<float>(seconds);
    if (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS) speed *= kFastMultiplier;
    if (move != glm::vec3(0.0f)) camera_.move(glm::normalize(move) * speed);

    // Mouse look while the right button is held, so the cursor stays free for the window otherwise.
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    const bool looking = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (looking && lookActive_) camera_.look(static_cast<float>(x - lastCursorX_), static_cast<float>(y - lastCursorY_));
    lookActive_ = looking;
    lastCursorX_ = x;
    lastCursorY_ = y;
}

void App::writeOutputs() {
    if (!options_.output.empty()) {
        if (width_ == 0 || height_ == 0) throw Error(options_.output + ": not written, the last frame was 0x0");
        createParentDirectory(options_.output);
        writePng(options_.output, readDefaultFramebuffer(width_, height_));
        std::cout << "wrote " << options_.output << "\n";
    }
    if (!options_.exr.empty()) {
        if (width_ == 0 || height_ == 0) throw Error(options_.exr + ": not written, the last frame was 0x0");
        createParentDirectory(options_.exr);
        writeExr(options_.exr, readTextureLevel(scene_->accumulationTexture(), 0, true));
        std::cout << "wrote " << options_.exr << "\n";
    }
    if (!options_.dumpDir.empty()) {
        std::filesystem::create_directories(options_.dumpDir);
        GLint active = 0;
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
        for (GLuint unit : {15u, 16u, 17u}) {
            glActiveTexture(GL_TEXTURE0 + unit);
            GLint texture = 0;
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
            if (texture == 0) continue;
            GLint levels = 0;
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
            for (int level = 0; level < std::max(levels, 1); ++level) {
                const std::string file = (std::filesystem::path(options_.dumpDir) /
                                          ("unit" + std::to_string(unit) + "_level" + std::to_string(level) + ".pfm"))
                                             .string();
                writePfm(file, readTextureLevel(static_cast<GLuint>(texture), level));
            }
        }
        glActiveTexture(static_cast<GLenum>(active));
        std::cout << "wrote textures of units 15-17 into " << options_.dumpDir << "\n";
    }
}

int App::run() {
    resize(width_, height_);
    const bool window = context_.isWindow();
    const int frames = options_.frames > 0 ? options_.frames : (window ? 0 : 1);
    std::vector<double> times;
    auto last = Clock::now();
    auto titleTime = last;
    for (int frame = 0; frames == 0 || frame < frames; ++frame) {
        context_.pollEvents();
        if (context_.shouldClose()) break;
        if (static_cast<std::size_t>(frame) < options_.resizeSequence.size()) {
            // Scripted resize (tests): the same path a window's size change takes.
            const auto [w, h] = options_.resizeSequence[static_cast<std::size_t>(frame)];
            context_.requestSize(w, h);
            resize(w, h);
        } else if (window) {
            int w = 0;
            int h = 0;
            context_.framebufferSize(w, h);
            if (w != width_ || h != height_) resize(w, h);
        }
        const double elapsed = secondsSince(last);
        last = Clock::now();
        handleInput(elapsed);
        if (width_ == 0 || height_ == 0) {
            if (window) glfwWaitEventsTimeout(0.1);
            continue;
        }
        const auto start = Clock::now();
        stage_.render(*this);
        views_->finishFrame(*quad_, width_, height_);
        if (!window) glFinish();
        const double renderMs = secondsSince(start) * 1000.0;
        frameTimeMs_ = window ? elapsed * 1000.0 : renderMs;
        glErrors_->pollGetError();
        if (!glErrors_->empty()) throw Error("GL error in frame " + std::to_string(frame) + ":" + glErrors_->describe());
        times.push_back(renderMs);
        if (options_.verbose) std::cout << "frame " << frame << ": " << renderMs << " ms\n";
        if (frames != 0 && frame == frames - 1) {
            writeOutputs();
            glErrors_->pollGetError();
            if (!glErrors_->empty()) throw Error("GL error while reading the outputs:" + glErrors_->describe());
        }
        if (window && secondsSince(titleTime) > kTitleInterval) {
            titleTime = Clock::now();
            char title[160];
            std::snprintf(title, sizeof title, "%s - %.1f ms (%.0f fps) - view %s (V)", stage_.name, frameTimeMs_,
                          frameTimeMs_ > 0.0 ? 1000.0 / frameTimeMs_ : 0.0, viewName(views_->current()));
            context_.setTitle(title);
        }
        context_.swapBuffers();
    }
    if (frames == 0 && (!options_.output.empty() || !options_.exr.empty() || !options_.dumpDir.empty())) {
        std::cerr << "note: --output, --exr and --dump are written after the last of --frames N frames\n";
    }
    if (options_.verbose && !times.empty()) {
        std::vector<double> sorted = times;
        std::sort(sorted.begin(), sorted.end());
        std::cout << "frames: " << times.size() << ", median frame time " << sorted[sorted.size() / 2] << " ms, mean "
                  << std::accumulate(times.begin(), times.end(), 0.0) / static_cast<double>(times.size()) << " ms\n";
    }
    return 0;
}

Image8 readDefaultFramebuffer(int width, int height) {
    Image8 image(width, height, 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    GLint drawBuffer = GL_BACK;
    glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
    glReadBuffer(static_cast<GLenum>(drawBuffer));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.data.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return image;
}

ImageF readTextureLevel(GLuint texture, int level, bool rgba) {
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    GLint previous = 0;
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    glBindTexture(GL_TEXTURE_2D, texture);
    GLint width = 0;
    GLint height = 0;
    GLint format = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_INTERNAL_FORMAT, &format);
    const bool single = format == GL_R16 || format == GL_R16F || format == GL_R32F || format == GL_R8;
    const int channels = rgba ? 4 : (single ? 1 : 3);
    ImageF image(width, height, channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, level, channels == 4 ? GL_RGBA : (channels == 1 ? GL_RED : GL_RGB), GL_FLOAT,
                  image.data.data());
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    glActiveTexture(static_cast<GLenum>(active));
    return image;
}

int runStage(int argc, const char* const* argv, const Stage& stage) {
    Options options;
    const int parsed = parseCommandLine(argc, argv, stage.name, stage.summary, options, stage.addOptions);
    if (parsed >= 0) return parsed;
    try {
        ContextOptions contextOptions;
        contextOptions.backend = options.backend;
        contextOptions.headless = options.headless;
        contextOptions.width = options.width;
        contextOptions.height = options.height;
        contextOptions.title = stage.name;
#ifdef T10_GL_DEBUG
        contextOptions.debug = true;
#endif
        std::unique_ptr<Context> context = Context::create(contextOptions);
        App app(stage, options, *context);
        return app.run();
    } catch (const UsageError& error) {
        std::cerr << stage.name << ": error: " << error.what() << "\n";
        return error.exitCode();
    } catch (const Error& error) {
        std::cerr << stage.name << ": error: " << error.what() << "\n";
        return error.exitCode();
    } catch (const std::exception& error) {
        std::cerr << stage.name << ": error: " << error.what() << "\n";
        return 1;
    }
}

} // namespace t10
