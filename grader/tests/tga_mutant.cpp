// tga_mutant: a TGA-to-PNG converter with one deliberate fault, to show that t10-grade-tga catches
// it. It decodes with the project's loader, then:
//   --flip    writes the image upside down          --swap    swaps red and blue
//   --crash   dies of SIGSEGV on every file         --hang    never finishes on rgb24_rle_bl.tga
//   --accept  turns a malformed file into a black 1x1 PNG and exits 0
// usage: tga_mutant MODE IN.tga OUT.png
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/tga.hpp"

#include <csignal>
#include <iostream>
#include <string>
#include <thread>
#include <utility>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: tga_mutant --flip|--swap|--crash|--hang|--accept IN.tga OUT.png\n";
        return 2;
    }
    const std::string mode = argv[1];
    if (mode == "--crash") std::raise(SIGSEGV);
    if (mode == "--hang" && std::string(argv[2]).find("rgb24_rle_bl.tga") != std::string::npos) {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    t10::Image8 image;
    try {
        image = t10::loadTga(argv[2]);
    } catch (const t10::Error& error) {
        if (mode != "--accept") {
            std::cerr << error.what() << "\n";
            return 1;
        }
        image = t10::Image8(1, 1, 3);
    }
    if (mode == "--flip") {
        for (int y = 0; y < image.height / 2; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < image.channels; ++c) std::swap(image.at(x, y, c), image.at(x, image.height - 1 - y, c));
    } else if (mode == "--swap" && image.channels >= 3) {
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) std::swap(image.at(x, y, 0), image.at(x, y, 2));
    }
    try {
        t10::writePng(argv[3], image);
    } catch (const t10::Error& error) {
        std::cerr << error.what() << "\n";
        return 1;
    }
    return 0;
}
