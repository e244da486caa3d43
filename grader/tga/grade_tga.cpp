// t10-grade-tga: grades a student's TGA loader through a converter command.
//   t10-grade-tga [--timeout S] [--report FILE.json] 'COMMAND {in} {out}'
// COMMAND is run by /bin/sh with {in} replaced by a TGA file and {out} by the PNG it must write (a
// student's converter, or their loader compiled against t10::loadTga's signature into a
// tga2png-like program). It runs over every TGA fixture of tests/fixtures/tga (reference PNGs
// written by an independent writer) and over malformed files derived from them, each under a time
// limit, and reports per case: right pixels, wrong orientation, wrong channel order, wrong pixels,
// rejected a valid file, crash, hang, accepted a malformed file, rejected (for malformed files).
// The score is the share of cases passed, rounded down. Exit 0 when every case ran, 1 when the
// harness failed, 2 on bad usage.
#include "isolation/run_limited.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<unsigned char>;

struct Case {
    std::string name;
    fs::path input;
    fs::path expected; // empty for a malformed file
};

struct Outcome {
    std::string name;
    bool malformed = false;
    bool passed = false;
    std::string verdict;
    std::string detail;
};

Bytes readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw t10::Error(path.string() + ": cannot open: " + std::strerror(errno));
    return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw t10::Error(path.string() + ": cannot write: " + std::strerror(errno));
}

// Malformed files, each derived from a valid fixture by one fault that the tests' loader rejects.
std::vector<Case> malformedCases(const fs::path& fixtures, const fs::path& work) {
    const Bytes raw = readBytes(fixtures / "rgb24_raw_bl.tga");
    const Bytes rle = readBytes(fixtures / "rgb24_rle_bl.tga");
    std::vector<std::pair<std::string, Bytes>> files;
    auto patched = [](Bytes b, std::size_t at, std::initializer_list<unsigned char> values) {
        for (unsigned char v : values) b[at++] = v;
        return b;
    };
    files.push_back({"empty", {}});
    files.push_back({"truncated_header", Bytes(raw.begin(), raw.begin() + 7)});
    files.push_back({"zero_width", patched(raw, 12, {0, 0})});
    Bytes huge = patched(raw, 12, {0x00, 0x40, 0x00, 0x40}); // 16384 x 16384 with 10 bytes of data
    huge.resize(18 + 10);
    files.push_back({"huge_size_no_data", huge});
    files.push_back({"colour_mapped_type_1", patched(raw, 2, {1})});
    files.push_back({"no_image_type_0", patched(raw, 2, {0})});
    files.push_back({"depth_16", patched(raw, 16, {16})});
    files.push_back({"right_to_left", patched(raw, 17, {0x10})});
    // One byte short of the pixel data (a file may carry a footer after it).
    const std::size_t pixelEnd = 18 + raw[0] + std::size_t(raw[12] | raw[13] << 8) * std::size_t(raw[14] | raw[15] << 8) * 3;
    files.push_back({"pixel_data_truncated", Bytes(raw.begin(), raw.begin() + static_cast<long>(pixelEnd) - 1)});
    files.push_back({"rle_truncated", Bytes(rle.begin(), rle.begin() + static_cast<long>(18 + (rle.size() - 18) / 2))});
    std::vector<Case> cases;
    for (const auto& [name, bytes] : files) {
        const fs::path path = work / ("malformed_" + name + ".tga");
        writeBytes(path, bytes);
        cases.push_back({"malformed_" + name, path, {}});
    }
    return cases;
}

// Expands grey to RGB and adds an opaque alpha, so that a converter may write any channel count.
t10::Image8 toRgba(const t10::Image8& image) {
    t10::Image8 out(image.width, image.height, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int source = image.channels == 1 ? 0 : image.channels == 2 ? (c == 3 ? 1 : 0) : c;
                out.at(x, y, c) = c == 3 && image.channels != 4 && image.channels != 2 ? 255 : image.at(x, y, std::min(source, image.channels - 1));
            }
    return out;
}

bool same(const t10::Image8& a, const t10::Image8& b, bool flip, bool swap) {
    if (a.width != b.width || a.height != b.height) return false;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int sy = flip ? a.height - 1 - y : y;
                const int sc = swap && c != 3 ? 2 - c : c;
                if (a.at(x, y, c) != b.at(x, sy, sc)) return false;
            }
    return true;
}

std::string quote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string substitute(std::string command, const std::string& in, const std::string& out) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{in}", in}, {"{out}", out}}) {
        for (auto at = command.find(key); at != std::string::npos; at = command.find(key, at + value.size())) {
            command.replace(at, key.size(), quote(value));
        }
    }
    return command;
}

std::string json(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

} // namespace

int main(int argc, char** argv) {
    double timeout = 10.0;
    std::string reportFile;
    std::string command;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if ((arg == "--timeout" || arg == "--report") && i + 1 < argc) {
            const std::string value = argv[++i];
            if (arg == "--report") {
                reportFile = value;
            } else {
                char* end = nullptr;
                timeout = std::strtod(value.c_str(), &end);
                if (*end != '\0' || !(timeout >= 1 && timeout <= 600)) {
                    std::cerr << "t10-grade-tga: error: --timeout " << value << ": expected 1 to 600 seconds\n";
                    return 2;
                }
            }
        } else if (arg == "--help" || arg == "-h") {
            std::cout << "usage: t10-grade-tga [--timeout S] [--report FILE.json] 'COMMAND {in} {out}'\n";
            return 0;
        } else if (!command.empty() || arg.rfind("--", 0) == 0) {
            std::cerr << "t10-grade-tga: error: unexpected argument " << arg
                      << "\nusage: t10-grade-tga [--timeout S] [--report FILE.json] 'COMMAND {in} {out}'\n";
            return 2;
        } else {
            command = arg;
        }
    }
    if (command.find("{in}") == std::string::npos || command.find("{out}") == std::string::npos) {
        std::cerr << "t10-grade-tga: error: the command must contain {in} and {out}, e.g. 'tga2png {in} {out}'\n";
        return 2;
    }
    try {
        const fs::path fixtures = T10_GRADE_TGA_FIXTURES;
        const fs::path work = fs::temp_directory_path() / ("t10-grade-tga." + std::to_string(::getpid()));
        fs::remove_all(work);
        fs::create_directories(work);
        std::vector<Case> cases;
        for (const auto& entry : fs::directory_iterator(fixtures)) {
            if (entry.path().extension() != ".tga") continue;
            fs::path png = entry.path();
            png.replace_extension(".png");
            if (fs::exists(png)) cases.push_back({entry.path().stem().string(), entry.path(), png});
        }
        std::sort(cases.begin(), cases.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
        if (cases.empty()) throw t10::Error(fixtures.string() + ": no TGA fixtures with reference PNGs");
        const std::vector<Case> malformed = malformedCases(fixtures, work);
        cases.insert(cases.end(), malformed.begin(), malformed.end());

        std::vector<Outcome> outcomes;
        for (const Case& c : cases) {
            Outcome o;
            o.name = c.name;
            o.malformed = c.expected.empty();
            const fs::path out = work / (c.name + ".out.png");
            const t10::grade::Limits limits{timeout, static_cast<int>(timeout) + 5, 2048};
            const auto result = t10::grade::runLimited({"/bin/sh", "-c", substitute(command, c.input.string(), out.string())},
                                                       limits, (work / (c.name + ".log")).string());
            if (result.timedOut) {
                o.verdict = "hang";
                o.detail = result.describe();
            } else if (result.signal != 0 || result.exitCode >= 128) {
                // sh reports a signalled child as 128 + signal.
                o.verdict = "crash";
                o.detail = result.signal != 0 ? result.describe() : "exit code " + std::to_string(result.exitCode) + " (signal " + std::to_string(result.exitCode - 128) + ")";
            } else if (o.malformed) {
                o.passed = result.exitCode != 0;
                o.verdict = o.passed ? "rejected" : "accepted a malformed file";
                o.detail = o.passed ? "exit code " + std::to_string(result.exitCode) : "exit code 0";
            } else if (result.exitCode != 0) {
                o.verdict = "rejected a valid file";
                o.detail = result.describe() + ": " + result.output.substr(0, 200);
            } else if (!fs::exists(out)) {
                o.verdict = "no output";
                o.detail = out.string() + " was not written";
            } else {
                try {
                    const t10::Image8 expected = toRgba(t10::readPng(c.expected.string()));
                    const t10::Image8 actual = toRgba(t10::readPng(out.string()));
                    if (same(expected, actual, false, false)) {
                        o.passed = true;
                        o.verdict = "right pixels";
                    } else if (same(expected, actual, true, false)) {
                        o.verdict = "wrong orientation";
                        o.detail = "upside down: the origin bit (descriptor bit 5) is ignored or inverted";
                    } else if (same(expected, actual, false, true)) {
                        o.verdict = "wrong channel order";
                        o.detail = "red and blue swapped: TGA stores BGR(A)";
                    } else if (same(expected, actual, true, true)) {
                        o.verdict = "wrong orientation and channel order";
                    } else {
                        o.verdict = "wrong pixels";
                        o.detail = std::to_string(actual.width) + "x" + std::to_string(actual.height) + ", expected " +
                                   std::to_string(expected.width) + "x" + std::to_string(expected.height);
                    }
                } catch (const t10::Error& error) {
                    o.verdict = "wrong pixels";
                    o.detail = error.what();
                }
            }
            outcomes.push_back(o);
        }
        fs::remove_all(work);

        int passed = 0;
        for (const Outcome& o : outcomes) {
            passed += o.passed ? 1 : 0;
            std::cout << (o.passed ? "pass  " : "FAIL  ") << o.name << ": " << o.verdict
                      << (o.detail.empty() ? "" : " (" + o.detail + ")") << "\n";
        }
        const int score = passed * 100 / static_cast<int>(outcomes.size());
        std::cout << "score " << score << " (" << passed << " of " << outcomes.size() << " cases)\n";
        if (!reportFile.empty()) {
            std::ostringstream out;
            out << "{\n  \"command\": " << json(command) << ",\n  \"score\": " << score << ",\n  \"cases\": [";
            for (std::size_t i = 0; i < outcomes.size(); ++i) {
                const Outcome& o = outcomes[i];
                out << (i ? "," : "") << "\n    {\"file\": " << json(o.name) << ", \"malformed\": " << (o.malformed ? "true" : "false")
                    << ", \"passed\": " << (o.passed ? "true" : "false") << ", \"verdict\": " << json(o.verdict)
                    << ", \"detail\": " << json(o.detail) << "}";
            }
            out << "\n  ]\n}\n";
            std::ofstream file(reportFile);
            file << out.str();
            if (!file) throw t10::Error(reportFile + ": cannot write: " + std::strerror(errno));
        }
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "t10-grade-tga: error: " << error.what() << "\n";
        return 1;
    }
}
