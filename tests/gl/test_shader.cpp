// Shader manager and texture loading against a real (headless, llvmpipe) GL context: success,
// and the error paths a student will hit first — a missing file and a compile error.
#include "t10/context.hpp"
#include "t10/error.hpp"
#include "t10/shader.hpp"
#include "t10/texture.hpp"

#include "t10_catch.hpp"

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
