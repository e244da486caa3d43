// The loops a page cannot bound (t10::unboundedLoops, common/content glsl_es.cpp; issue 52, item 6): what
// Module.t10SetShader refuses, each at its line, before a compiler or a GPU sees it, so that a student's
// shader cannot hang the browser. The one implementation of the rule: the page's editor shows what the
// page answers.
// It can fail: each refused case names the lines it must be refused at (a check that refused nothing, or
// everything, or at the wrong line, fails), and the accepted cases (the bounded loops a blur would write,
// "for" inside a name, a loop in a comment, loops one after the other, an if-else body) fail a check that
// refuses too much.
#include "t10/error.hpp"
#include "t10/glsl_es.hpp"

#include "repository_shaders.hpp"
#include "t10_catch.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace {

std::vector<int> refusedLines(const std::string& source) {
    std::vector<int> lines;
    for (const t10::ShaderMessage& m : t10::unboundedLoops(source, "in.frag")) lines.push_back(m.line);
    return lines;
}

std::string repeated(const std::string& text, int times) {
    std::string out;
    for (int i = 0; i < times; ++i) out += text;
    return out;
}

struct Case {
    const char* what;
    std::string source;
    std::vector<int> lines;
};

} // namespace

TEST_CASE("loops a page can bound pass, the others are refused at their lines", "[glsl_es][loops]") {
    const std::vector<Case> cases = {
        // The editor's 17 cases (site/tests/editor_loops_test.js before the rule moved here).
        {"no loop", "void main() { float fY = 1.0; }", {}},
        {"a fixed count", "void main() {\n  for (int i = 0; i < 5; ++i) { fY += 1.0; }\n}", {}},
        {"counting down", "for (int i = 4; i >= 0; i--) fY++;", {}},
        {"a blur's taps", "for (int i = -2; i <= 2; i += 1) { }", {}},
        {"two loops one after the other", "for (int i = 0; i < 1000; ++i) { }\nfor (int j = 0; j < 1000; ++j) { }", {}},
        {"nested within the budget", "for (int i = 0; i < 30; ++i) {\n  for (int j = 0; j < 30; ++j) { }\n}", {}},
        {"for and while inside names and comments", "float forward, format; // while (true)\n/* do { } */", {}},
        {"a while loop", "float a;\n\n  while (true) { }", {3}},
        {"a do loop", "do {\n} while (fY < 1.0);", {1, 2}},
        {"a bound from a variable", "\nfor (int i = 0; i < n; ++i) { }", {2}},
        {"too many iterations", "for (int i = 0; i < 100000; ++i) { }", {1}},
        {"counting away from the bound", "for (int i = 0; i < 10; --i) { }", {1}},
        {"a float counter", "for (float f = 0.0; f < 1.0; f += 0.1) { }", {1}},
        {"the counter changed in the body", "for (int i = 0; i < 5; ++i) {\n  i = 0;\n}", {1}},
        {"nested past the budget", "for (int i = 0; i < 100; ++i) {\n  for (int j = 0; j < 100; ++j) { }\n}", {2}},
        {"nested without braces", "for (int i = 0; i < 100; ++i)\n  for (int j = 0; j < 100; ++j) fY++;", {2}},
        {"a loop spelt by token pasting", "#define LOOP(a, b) a ## b\nLOOP(wh, ile) (true) { }", {1}},
        // What the token reading adds: calls, macros, statements and int's range.
        {"a while hidden in a macro", "#define W while\nvoid main() {\n  W (true) { }\n}", {1}},
        {"a call of a function with loops inside a loop",
         "float f() { float s = 0.0; for (int i = 0; i < 100; ++i) s += 1.0; return s; }\n"
         "void main() {\n  for (int j = 0; j < 100; ++j) { fY += f(); }\n}", {3}},
        {"the same call within the budget",
         "float f() { float s = 0.0; for (int i = 0; i < 100; ++i) s += 1.0; return s; }\n"
         "void main() {\n  for (int j = 0; j < 10; ++j) { fY += f(); }\n}", {}},
        {"calls multiply through functions",
         "float f() { float s = 0.0; for (int i = 0; i < 10; ++i) s += 1.0; return s; }\n"
         "float g() { float s = 0.0; for (int i = 0; i < 10; ++i) s += f(); return s; }\n"
         "void main() {\n  for (int j = 0; j < 20; ++j) fY += g();\n}", {4}},
        {"the counter passed to an inout parameter",
         "void reset(inout int x) { x = 0; }\nvoid main() {\n  for (int i = 0; i < 5; ++i) { reset(i); }\n}", {3}},
        {"the counter passed to an in parameter", "float w(int x) { return 1.0; }\nvoid main() {\n  for (int i = 0; i < 5; ++i) { fY += w(i); }\n}", {}},
        {"the counter shifted in the body", "for (int i = 1; i < 5; ++i) {\n  i >>= 1;\n}", {1}},
        {"the counter compared in the body", "for (int i = 0; i < 5; ++i) { if (i == 2 || i <= 1 || i != 3) fY++; }", {}},
        {"a macro naming a function with loops",
         "float f() { for (int i = 0; i < 100; ++i) { } return 0.0; }\n#define CALL f\n"
         "void main() { for (int j = 0; j < 100; ++j) fY += CALL(); }", {2}},
        {"a counter that is a macro", "#define i j\nfor (int i = 0; i < 5; ++i) { j = 0; }", {2}},
        {"a macro that changes the counter", "#define RESET i = 0\nfor (int i = 0; i < 5; ++i) { RESET; }", {2}},
        {"a macro that names one that changes the counter",
         "#define ZERO i = 0\n#define RESET ZERO\nfor (int i = 0; i < 5; ++i) { RESET; }", {3}},
        {"the counter passed to a macro", "#define RESET(x) x = 0\nfor (int i = 0; i < 5; ++i) { RESET(i); }", {2}},
        {"a macro the body uses that leaves the counter alone", "#define HALF 0.5\nfor (int i = 0; i < 5; ++i) { fY *= HALF; }", {}},
        {"a function named by a macro", "#define NAME helper\nvoid NAME() { }", {2}},
        {"a macro calling its parameter", "#define CALL(fn) fn()", {1}},
        {"an if-else body ends where its else ends",
         "for (int i = 0; i < 100; ++i)\n  if (fY > 0.0) fY++; else fY--;\nfor (int j = 0; j < 100; ++j) { }", {}},
        {"a loop in the else of a loop's body",
         "for (int i = 0; i < 100; ++i)\n  if (fY > 0.0) fY++;\n  else for (int j = 0; j < 100; ++j) fY--;", {3}},
        {"a step that leaves int", "for (int i = 0; i < 2147483647; i += 2000000000) { }", {1}},
        {"a condition on another variable", "for (int i = 0; j < 5; ++i) { }", {1}},
        {"an empty head", "for (;;) { }", {1}},
        {"an unclosed body", "for (int i = 0; i < 5; ++i) {", {}},
        {"more loops than the page reads", repeated("for (int i = 0; i < 1; ++i) { }\n", 129), {129}},
    };
    for (const Case& c : cases) {
        INFO(c.what << ":\n" << c.source);
        CHECK(refusedLines(c.source) == c.lines);
    }
}

TEST_CASE("a refusal says what is refused and how to write it", "[glsl_es][loops]") {
    const std::vector<t10::ShaderMessage> found = t10::unboundedLoops("void main() {\n  while (true) { }\n}", "in.frag");
    REQUIRE(found.size() == 1);
    CHECK(found[0].line == 2);
    CHECK(found[0].message.find("a while loop") == 0);
    CHECK(found[0].message.find("for (int i = 0; i < N; ++i), N at most 1024") != std::string::npos);
    const std::vector<t10::ShaderMessage> nested =
        t10::unboundedLoops("for (int i = 0; i < 100; ++i)\n  for (int j = 0; j < 100; ++j) fY++;", "in.frag");
    REQUIRE(nested.size() == 1);
    CHECK(nested[0].message.find("nested loops that run 10000 times for a pixel") == 0);
}

TEST_CASE("text the translator cannot read is its error, not a loop", "[glsl_es][loops]") {
    CHECK_THROWS_AS(t10::unboundedLoops("/* never closed", "in.frag"), t10::Error);
    CHECK_THROWS_AS(t10::unboundedLoops(std::string("a\0b", 3), "in.frag"), t10::Error);
}

TEST_CASE("hostile loops are read quickly and listed at most 50 at a time", "[glsl_es][loops]") {
    // 1 MiB of loops nested without braces: each loop read reads its body to the end (quadratic), so the
    // page reads at most 128 of them; the rest are refused unread.
    std::string source = repeated("for (int i = 0; i < 1; ++i)\n", 37000) + "fY++;";
    const auto start = std::chrono::steady_clock::now();
    const std::vector<t10::ShaderMessage> found = t10::unboundedLoops(source, "in.frag");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 5.0); // generous for a loaded machine: quadratic in 37000 loops would take minutes
    REQUIRE(found.size() == 51); // each loop's body steps an i (the next loop's): all refused
    CHECK(found.front().line == 1);
    CHECK(found.back().line == 0);
    CHECK(found.back().message.find("more") != std::string::npos);
}

TEST_CASE("the stages' own shaders, which the page lets a student edit, have no loop it refuses", "[glsl_es][loops]") {
    // common/shaders/ (the scene's parallax search) is not edited in the page: only the stage folders are.
    for (const auto& file : t10::test::repositoryShaders()) {
        if (file.parent_path().parent_path().filename() == "common" || file.string().find("/common/") != std::string::npos) continue;
        INFO(file.string());
        CHECK(t10::unboundedLoops(t10::test::readText(file), file.filename().string()).empty());
    }
}
