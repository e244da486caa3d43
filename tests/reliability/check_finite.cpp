// check_finite: checks a --dump folder rendered from an --input image with an infinite pixel: every
// level of every texture (the *.pfm files) holds only finite values, and the final frame (frame.png)
// shows the infinite pixel saturated, not black (inf / inf in the tone map gave black before).
// X and Y count from the image's top-left corner, as in the input file.
// usage: check_finite DUMP_DIR X Y
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: check_finite DUMP_DIR X Y\n";
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        const int x = std::stoi(argv[2]);
        const int yFromTop = std::stoi(argv[3]);
        int failures = 0;
        int files = 0;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (entry.path().extension() != ".pfm") continue;
            ++files;
            const t10::ImageF level = t10::readPfm(entry.path().string());
            std::size_t bad = 0;
            for (const float value : level.data) bad += std::isfinite(value) ? 0 : 1;
            if (bad > 0) {
                std::cout << entry.path().filename().string() << ": " << bad << " values are not finite\n";
                ++failures;
            }
        }
        if (files == 0) {
            std::cout << dir.string() << ": no .pfm files\n";
            return 1;
        }
        const t10::Image8 frame = t10::readPng((dir / "frame.png").string());
        const int y = frame.height - 1 - yFromTop; // rows are held bottom first
        const int red = frame.at(x, y, 0);
        std::cout << files << " texture levels checked; frame pixel (" << x << ", " << yFromTop << ") is (" << red
                  << ", " << int(frame.at(x, y, 1)) << ", " << int(frame.at(x, y, 2)) << ")\n";
        // The infinite value is in the red channel: it must saturate red (255), whatever the stage does.
        if (red != 255) {
            std::cout << "the infinite pixel is not saturated: red " << red << ", expected 255\n";
            ++failures;
        }
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "check_finite: error: " << error.what() << "\n";
        return 1;
    }
}
