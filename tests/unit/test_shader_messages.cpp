// The page's shader errors as lines of the student's file (common/content shader_messages.hpp): the
// UTF-8 check, and the compiler logs and translator errors read into {line, message}. Each check is
// shown to reject: a wrong line, a dropped message or an accepted bad byte fails an expectation below.
#include "t10/shader_messages.hpp"

#include "t10_catch.hpp"

using t10::ShaderMessage;

TEST_CASE("utf8Problem accepts UTF-8 text and names the line and byte of the first fault", "[shader_messages]") {
    CHECK_FALSE(t10::utf8Problem("#version 430 core\n// caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\n").has_value());
    CHECK_FALSE(t10::utf8Problem("").has_value());
    const auto lone = t10::utf8Problem("a\nb\xff");
    REQUIRE(lone.has_value());
    CHECK(lone->line == 2);
    CHECK_THAT(lone->message, Catch::Contains("byte 2") && Catch::Contains("0xff"));
    // Overlong, surrogate, above U+10FFFF, truncated: each refused, as UTF-8 defines.
    for (const char* bad : {"\xc0\xaf", "\xe0\x80\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82", "\x80"}) {
        INFO(bad);
        CHECK(t10::utf8Problem(std::string("x") + bad).has_value());
    }
}

TEST_CASE("lineCount counts a last line without its newline", "[shader_messages]") {
    CHECK(t10::lineCount("") == 1);
    CHECK(t10::lineCount("a") == 1);
    CHECK(t10::lineCount("a\nb") == 2);
    CHECK(t10::lineCount("a\nb\n") == 3);
}

TEST_CASE("compilerMessages reads ANGLE's and Mesa's logs into lines of the file", "[shader_messages]") {
    const auto angle = t10::compilerMessages("ERROR: 0:12: 'x' : undeclared identifier\n"
                                             "ERROR: 0:14: 'y' : syntax error\n"
                                             "ERROR: 2 compilation errors.  No code generated.\n\n",
                                             20);
    REQUIRE(angle.size() == 2);
    CHECK(angle[0].line == 12);
    CHECK(angle[0].message == "'x' : undeclared identifier");
    CHECK(angle[1].line == 14);
    const auto mesa = t10::compilerMessages("0:7(3): error: `v' undeclared\n", 20);
    REQUIRE(mesa.size() == 1);
    CHECK(mesa[0].line == 7);
    CHECK(mesa[0].message == "`v' undeclared");
    // No line (ANGLE's -1) and a line past the file's end (generated code) are the file as a whole.
    const auto whole = t10::compilerMessages("ERROR: -1:-1: '' : Missing main()\nERROR: 0:99: 'z' : oops\n", 20);
    REQUIRE(whole.size() == 2);
    CHECK(whole[0].line == 0);
    CHECK(whole[0].message == "'' : Missing main()");
    CHECK(whole[1].line == 0);
    // A log in no known form is kept whole rather than lost.
    const auto odd = t10::compilerMessages("something went wrong\n", 20);
    REQUIRE(odd.size() == 1);
    CHECK(odd[0].line == 0);
    CHECK(odd[0].message == "something went wrong");
}

TEST_CASE("translatorMessage takes the file's name off and keeps its line", "[shader_messages]") {
    const ShaderMessage m = t10::translatorMessage("Gauss.frag:5: `double` cannot be translated", "Gauss.frag", 30);
    CHECK(m.line == 5);
    CHECK(m.message == "`double` cannot be translated");
    const ShaderMessage whole = t10::translatorMessage("Gauss.frag: 2000000 bytes is more", "Gauss.frag", 30);
    CHECK(whole.line == 0);
    CHECK(whole.message == "2000000 bytes is more");
    CHECK(t10::translatorMessage("Gauss.frag:31: past the end", "Gauss.frag", 30).line == 0);
}
