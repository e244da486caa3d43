// The harness t10-grade-tga builds a student's TGA loader with: it decodes one file through the
// student's t10::loadTga (t10/tga.hpp's signature) and writes what came back as a raw image for the
// grader to compare. Built and run inside the grader's sandbox, on a copy of the input alone in its
// folder; the reference images are never there.
//   loader IN.tga OUT.raw
// OUT.raw: "T10RAW <width> <height> <channels>\n", then the pixels as t10::Image8 holds them (bottom
// row first, channels interleaved). Exit 0 decoded, 1 the loader threw (its message on stderr),
// 2 bad usage, 3 the output could not be written.
#include "t10/tga.hpp"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fputs("usage: loader IN.tga OUT.raw\n", stderr);
        return 2;
    }
    t10::Image8 image;
    try {
        image = t10::loadTga(argv[1]);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "the loader threw: %s\n", error.what());
        return 1;
    } catch (...) {
        std::fputs("the loader threw something that is not a std::exception\n", stderr);
        return 1;
    }
    std::FILE* out = std::fopen(argv[2], "wb");
    if (out == nullptr) return 3;
    std::fprintf(out, "T10RAW %d %d %d\n", image.width, image.height, image.channels);
    const bool written = std::fwrite(image.data.data(), 1, image.data.size(), out) == image.data.size();
    return std::fclose(out) == 0 && written ? 0 : 3;
}
