// halo_radius: how far the bloom of a hot spot spreads, from a stage's --dump folder. Prints the
// RMS radius of the bloom texture's luminance around its centroid, in full-resolution pixels:
// sqrt(sum(Y r^2) / sum(Y)). The bloom is read from the level the final pass reads: level 1 (half
// resolution, texel centres scaled by 2) after one or more blur passes, level 0 with none.
// Used by tools/bench_passes/bench_passes.sh on the hot-pixel input (tools/make_test_images).
// usage: halo_radius DUMP_DIR BLUR_PASSES
#include "t10/error.hpp"
#include "t10/contract.hpp"
#include "t10/image_io.hpp"
#include "t10/outputs.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: halo_radius DUMP_DIR BLUR_PASSES\n";
        return 2;
    }
    try {
        const int passes = std::stoi(argv[2]);
        const int level = passes > 0 ? 1 : 0;
        const double scale = passes > 0 ? 2.0 : 1.0; // texel size in full-resolution pixels
        const t10::ImageF bloom =
            t10::readPfm(std::string(argv[1]) + "/" + t10::dumpFileName(t10::contract::kBloomUnit, level));
        double sum = 0.0;
        double sumX = 0.0;
        double sumY = 0.0;
        for (int y = 0; y < bloom.height; ++y)
            for (int x = 0; x < bloom.width; ++x) {
                const double v = 0.2126 * bloom.at(x, y, 0) + 0.7152 * bloom.at(x, y, 1) + 0.0722 * bloom.at(x, y, 2);
                sum += v;
                sumX += v * (x + 0.5) * scale;
                sumY += v * (y + 0.5) * scale;
            }
        if (!(sum > 0.0)) throw t10::Error(std::string(argv[1]) + ": the bloom texture is empty");
        const double cx = sumX / sum;
        const double cy = sumY / sum;
        double moment = 0.0;
        for (int y = 0; y < bloom.height; ++y)
            for (int x = 0; x < bloom.width; ++x) {
                const double v = 0.2126 * bloom.at(x, y, 0) + 0.7152 * bloom.at(x, y, 1) + 0.0722 * bloom.at(x, y, 2);
                const double dx = (x + 0.5) * scale - cx;
                const double dy = (y + 0.5) * scale - cy;
                moment += v * (dx * dx + dy * dy);
            }
        std::printf("%.4f\n", std::sqrt(moment / sum));
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "halo_radius: error: " << error.what() << "\n";
        return 1;
    }
}
