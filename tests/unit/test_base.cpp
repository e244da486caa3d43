// The base layer's shared helpers: one median, one size parser, one JSON writer (used by the bench
// driver, the frame loop, the bench tools and, later, the grader).
#include "t10/args.hpp"
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/json.hpp"
#include "t10/stats.hpp"

#include "t10_catch.hpp"

#include <filesystem>
#include <string>
#include <vector>

TEST_CASE("median: the middle value, or the mean of the two middle values", "[base]") {
    CHECK(t10::median({}) == 0.0);
    CHECK(t10::median({4.0}) == 4.0);
    CHECK(t10::median({3.0, 1.0, 2.0}) == 2.0);
    // An even count averages the two middle values (the frame loop used to take the upper one: 3).
    CHECK(t10::median({4.0, 1.0, 3.0, 2.0}) == 2.5);
    CHECK(t10::median({5.0, 5.0, 1.0, 9.0}) == 5.0);
}

TEST_CASE("hasSuffix ignores the case of the name", "[base]") {
    CHECK(t10::hasSuffix("frame.PNG", ".png"));
    CHECK(t10::hasSuffix("a.glb", ".glb"));
    CHECK_FALSE(t10::hasSuffix("png", ".png"));
    CHECK_FALSE(t10::hasSuffix("frame.png.txt", ".png"));
}

TEST_CASE("parseSize takes the caller's limits", "[base]") {
    CHECK(t10::parseSize("8192x2", 2, 8192) == std::pair<int, int>(8192, 2));
    CHECK_THROWS_AS(t10::parseSize("8193x2", 2, 8192), t10::UsageError);
    CHECK_THROWS_WITH(t10::parseSize("640x", 2, 8192), Catch::Contains("'640x' is not WIDTHxHEIGHT"));
}

TEST_CASE("the JSON writer escapes strings and writes the file whole", "[base]") {
    const nlohmann::json report = {{"name", "quote \" backslash \\ newline \n tab \t"}, {"score", 0.5}};
    const std::string text = t10::jsonText(report);
    CHECK(text.back() == '\n');
    CHECK(text.find(R"(quote \" backslash \\ newline \n tab \t)") != std::string::npos);
    CHECK(nlohmann::json::parse(text) == report);
    // Invalid UTF-8 in a string becomes U+FFFD instead of failing the whole report.
    CHECK_NOTHROW(t10::jsonText(nlohmann::json{{"bad", std::string("\xff")}}));

    const std::string dir = std::string(T10_TEST_TMP_DIR) + "/json";
    std::filesystem::create_directories(dir);
    t10::writeJsonFile(dir + "/report.json", report);
    const std::vector<std::uint8_t> bytes = t10::readFile(dir + "/report.json");
    CHECK(std::string(bytes.begin(), bytes.end()) == text);
    // A folder that does not exist: the error names the file.
    CHECK_THROWS_WITH(t10::writeJsonFile(dir + "/missing/report.json", report),
                      Catch::Contains("missing/report.json: cannot write JSON"));
}

TEST_CASE("jsonQuoted gives valid JSON and UTF-8 for any bytes", "[base]") {
    // A compiler's line as a student's shader can make it: a bare 0xff, a cut-off sequence, a UTF-16
    // surrogate in UTF-8 form, a carriage return, a NUL and an escape character.
    const std::string bytes = std::string("#error \xff caf\xc3 \xed\xa0\x80 ok \xc3\xa9\r") + std::string(1, '\0') + "\x1b[0m\"q";
    const std::string quoted = t10::jsonQuoted(bytes);
    CHECK(quoted.front() == '"');
    CHECK(quoted.back() == '"');
    // Parsing checks the UTF-8 as well as the syntax.
    std::string parsed;
    REQUIRE_NOTHROW(parsed = nlohmann::json::parse(quoted).get<std::string>());
    CHECK(parsed.find("\xef\xbf\xbd") != std::string::npos);  // U+FFFD in place of the bad bytes
    CHECK(parsed.find("ok \xc3\xa9\r") != std::string::npos); // valid UTF-8 and \r kept as they were
    CHECK(quoted.find("\\r") != std::string::npos);
    CHECK(quoted.find("\\u0000") != std::string::npos);
    CHECK(quoted.find("\\u001b") != std::string::npos);
    CHECK(t10::jsonQuoted("plain") == "\"plain\"");
}
