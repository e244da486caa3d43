// exrstat: prints the largest RGB value of an OpenEXR image; with --min-max V it exits 1 unless the
// largest value exceeds V (the test that the accumulation buffer really holds HDR values).
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--min-max")) {
        std::cerr << "usage: exrstat FILE.exr [--min-max VALUE]\n";
        return 2;
    }
    try {
        const t10::ImageF image = t10::readExr(argv[1]);
        float largest = 0.0f;
        std::size_t above = 0;
        for (std::size_t i = 0; i < image.data.size(); ++i) {
            if (i % 4 == 3) continue; // alpha
            largest = std::max(largest, image.data[i]);
            if (image.data[i] > 1.0f) ++above;
        }
        std::cout << argv[1] << ": " << image.width << "x" << image.height << ", largest value " << largest << ", "
                  << above << " channel values above 1.0\n";
        if (argc == 4 && !(largest > std::stof(argv[3]))) {
            std::cout << "FAIL: largest value is not above " << argv[3] << "\n";
            return 1;
        }
        return 0;
    } catch (const t10::Error& error) {
        std::cerr << "exrstat: error: " << error.what() << "\n";
        return 1;
    }
}
