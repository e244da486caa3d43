// Shader manager and texture loading against a real (headless, llvmpipe) GL context: success,
// and the error paths a student will hit first — a missing file and a compile error.
#include "t10/context.hpp"
#include "t10/error.hpp"
#include "t10/shader.hpp"
#include "t10/mipmaps.hpp"
#include "t10/texture.hpp"
#include "t10/tga.hpp"

#include "t10_catch.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace {

t10::Context& context() {
    static std::unique_ptr<t10::Context> instance = [] {
        t10::ContextOptions options;
        options.headless = true;
        options.width = 16;
        options.height = 16;
        return t10::Context::create(options);
    }();
    return *instance;
}

// One folder per test case: ctest runs the cases as separate processes, in parallel.
std::filesystem::path scratch(const std::string& testCase) {
    const std::filesystem::path dir = std::filesystem::path(T10_TEST_TMP_DIR) / "shaders" / testCase;
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

} // namespace

TEST_CASE("a valid program compiles and links", "[shader]") {
    context();
    const auto dir = scratch("valid");
    write(dir / "Ok.vert", "#version 430 core\nlayout(location = 0) in vec2 p;\nvoid main() { gl_Position = vec4(p, 0, 1); }\n");
    write(dir / "Ok.frag", "#version 430 core\nout vec4 c;\nvoid main() { c = vec4(1); }\n");
    t10::ShaderManager shaders({dir.string()});
    const GLuint program = shaders.createProgram({"Ok.vert", "Ok.frag"});
    CHECK(program != 0);
    glDeleteProgram(program);
}

TEST_CASE("earlier folders win over later ones", "[shader]") {
    const auto dir = scratch("order");
    const auto first = dir / "first";
    std::filesystem::create_directories(first);
    write(first / "Ok.frag", "// override\n");
    write(dir / "Ok.frag", "// fallback\n");
    write(dir / "Ok.vert", "// only in the later folder\n");
    t10::ShaderManager shaders({first.string(), dir.string()});
    CHECK(shaders.find("Ok.frag") == (first / "Ok.frag").string());
    CHECK(shaders.find("Ok.vert") == (dir / "Ok.vert").string());
}

TEST_CASE("a compile error names the file and quotes the driver log", "[shader]") {
    context();
    const auto dir = scratch("compile");
    write(dir / "Ok.vert", "#version 430 core\nlayout(location = 0) in vec2 p;\nvoid main() { gl_Position = vec4(p, 0, 1); }\n");
    write(dir / "Broken.frag", "#version 430 core\nout vec4 c;\nvoid main() { c = not_declared; }\n");
    t10::ShaderManager shaders({dir.string()});
    try {
        shaders.createProgram({"Ok.vert", "Broken.frag"});
        FAIL("no error");
    } catch (const t10::Error& error) {
        const std::string message = error.what();
        CHECK_THAT(message, Catch::Contains("Broken.frag: shader compilation failed"));
        CHECK_THAT(message, Catch::Contains("not_declared"));
        CHECK(error.exitCode() == 1);
    }
}

TEST_CASE("a link error names the files", "[shader]") {
    context();
    const auto dir = scratch("link");
    write(dir / "Ok.vert", "#version 430 core\nlayout(location = 0) in vec2 p;\nvoid main() { gl_Position = vec4(p, 0, 1); }\n");
    write(dir / "NoMain.frag", "#version 430 core\nout vec4 c;\nvoid helper() { c = vec4(0); }\n");
    t10::ShaderManager shaders({dir.string()});
    CHECK_THROWS_WITH(shaders.createProgram({"Ok.vert", "NoMain.frag"}), Catch::Contains("program link failed"));
}

TEST_CASE("a missing shader lists every folder searched", "[shader]") {
    t10::ShaderManager shaders({"/no/such/a", "/no/such/b"});
    CHECK_THROWS_WITH(shaders.find("Missing.frag"),
                      Catch::Contains("Missing.frag") && Catch::Contains("/no/such/a") && Catch::Contains("/no/such/b"));
}

TEST_CASE("an unknown extension is an error, not a guess", "[shader]") {
    const auto dir = scratch("unknown");
    write(dir / "Odd.glsl", "void main() {}\n");
    t10::ShaderManager shaders({dir.string()});
    context();
    CHECK_THROWS_WITH(shaders.createProgram({"Odd.glsl"}), Catch::Contains("unknown shader stage"));
}

TEST_CASE("a missing texture names the path", "[texture]") {
    context();
    CHECK_THROWS_WITH(t10::loadTextureTga("/no/such/texture.tga", false), Catch::Contains("/no/such/texture.tga"));
}

// The CPU mip levels (mipmaps.hpp) beside what the driver's glGenerateMipmap makes of the scene's own
// linear textures (a normal map and a height map), every level down to 1x1. On llvmpipe they are the
// same bytes, which keeps every golden frame unchanged; on another driver the filter is its own (GL
// leaves it to the implementation), so elsewhere the bound is one 8-bit step. A point-sampled level
// (the first texel of each 2x2 block) is what the bound must reject.
TEST_CASE("CPU mip levels of linear textures are glGenerateMipmap's", "[texture]") {
    context();
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const int bound = renderer.find("llvmpipe") != std::string::npos ? 0 : 1;
    for (const char* file : {"bricks_normal.tga", "bricks_depth.tga"}) {
        const t10::Image8 image = t10::loadTga(std::string(T10_SOURCE_ROOT) + "/common/assets/" + file);
        const GLenum format = image.channels == 1 ? GL_RED : GL_RGB;
        GLuint texture = 0;
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexStorage2D(GL_TEXTURE_2D, 9, image.channels == 1 ? GL_R8 : GL_RGB8, image.width, image.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, format, GL_UNSIGNED_BYTE, image.data.data());
        glGenerateMipmap(GL_TEXTURE_2D);
        REQUIRE((image.width == 256 && image.height == 256));
        t10::Image8 cpu = image;
        for (int level = 1; level < 9; ++level) {
            const t10::Image8 above = cpu;
            cpu = t10::nextMipLevel(above);
            t10::Image8 gpu(cpu.width, cpu.height, cpu.channels);
            glGetTexImage(GL_TEXTURE_2D, level, format, GL_UNSIGNED_BYTE, gpu.data.data());
            int largest = 0;
            int pointLargest = 0;
            for (int y = 0; y < cpu.height; ++y)
                for (int x = 0; x < cpu.width; ++x)
                    for (int c = 0; c < cpu.channels; ++c) {
                        largest = std::max(largest, std::abs(int(cpu.at(x, y, c)) - int(gpu.at(x, y, c))));
                        pointLargest = std::max(pointLargest, std::abs(int(above.at(2 * x, 2 * y, c)) - int(gpu.at(x, y, c))));
                    }
            INFO(file << " level " << level << " on " << renderer);
            CHECK(largest <= bound);
            if (level < 6) CHECK(pointLargest > bound); // (the smallest levels of a smooth map may agree)
        }
        glDeleteTextures(1, &texture);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
}
