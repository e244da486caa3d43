// Implementation of the golden-image tolerance model; see compare.hpp.
#include "t10/compare.hpp"

#include "t10/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace t10::test {

Tolerance readTolerance(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open tolerance file");
    Tolerance tolerance;
    bool haveThreshold = false;
    bool haveFraction = false;
    bool haveMean = false;
    int lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        const auto equals = line.find('=');
        const auto hash = line.find('#');
        const std::string where = path + ":" + std::to_string(lineNumber);
        if (equals == std::string::npos) throw Error(where + ": expected 'key = value  # reason'");
        if (hash == std::string::npos || line.find_first_not_of(" \t", hash + 1) == std::string::npos) {
            throw Error(where + ": every bound needs its reason after '#'");
        }
        std::string key = line.substr(0, equals);
        key.erase(key.find_last_not_of(" \t") + 1);
        key.erase(0, key.find_first_not_of(" \t"));
        std::istringstream value(line.substr(equals + 1, hash - equals - 1));
        double number = 0.0;
        if (!(value >> number) || number < 0.0) throw Error(where + ": '" + key + "' needs a non-negative number");
        if (key == "threshold") {
            tolerance.threshold = static_cast<int>(number);
            haveThreshold = true;
        } else if (key == "max_fraction") {
            tolerance.maxFraction = number;
            haveFraction = true;
        } else if (key == "max_mean") {
            tolerance.maxMean = number;
            haveMean = true;
        } else {
            throw Error(where + ": unknown key '" + key + "' (threshold, max_fraction, max_mean)");
        }
    }
    if (!haveThreshold || !haveFraction || !haveMean) {
        throw Error(path + ": needs threshold, max_fraction and max_mean");
    }
    return tolerance;
}

ImageDifference imageDifference(const Image8& a, const Image8& b, int threshold) {
    ImageDifference result;
    const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
    if (pixels == 0) return result;
    std::size_t over = 0;
    double sum = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < a.channels; ++c) {
            const std::size_t i = p * static_cast<std::size_t>(a.channels) + static_cast<std::size_t>(c);
            const int difference = std::abs(int(a.data[i]) - int(b.data[i]));
            worst = std::max(worst, difference);
            sum += difference;
        }
        result.maxError = std::max(result.maxError, worst);
        if (worst > threshold) ++over;
    }
    result.fractionOverThreshold = double(over) / double(pixels);
    result.meanError = sum / double(pixels * static_cast<std::size_t>(a.channels));
    return result;
}

Comparison compareImages(const Image8& expected, const Image8& actual, const Tolerance& tolerance) {
    Comparison result;
    std::ostringstream summary;
    result.sizeMatches = expected.width == actual.width && expected.height == actual.height &&
                         expected.channels == actual.channels;
    if (!result.sizeMatches) {
        summary << "size differs: expected " << expected.width << "x" << expected.height << "x" << expected.channels
                << ", got " << actual.width << "x" << actual.height << "x" << actual.channels;
        result.summary = summary.str();
        return result;
    }
    const ImageDifference difference = imageDifference(expected, actual, tolerance.threshold);
    result.maxError = difference.maxError;
    result.failingFraction = difference.fractionOverThreshold;
    result.meanError = difference.meanError;
    result.passed = result.failingFraction <= tolerance.maxFraction && result.meanError <= tolerance.maxMean;
    summary << "failing pixels " << result.failingFraction * 100.0 << "% (max " << tolerance.maxFraction * 100.0
            << "%, threshold " << tolerance.threshold << "), mean error " << result.meanError << " (max "
            << tolerance.maxMean << "), largest channel error " << result.maxError;
    result.summary = summary.str();
    return result;
}

Image8 differenceHeatMap(const Image8& expected, const Image8& actual) {
    Image8 map(actual.width, actual.height, 3);
    if (expected.width != actual.width || expected.height != actual.height || expected.channels != actual.channels) {
        return map;
    }
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int worst = 0;
            for (int c = 0; c < actual.channels; ++c) {
                worst = std::max(worst, std::abs(int(expected.at(x, y, c)) - int(actual.at(x, y, c))));
            }
            const int v = std::min(worst * 4, 765); // x4 so small differences show
            map.at(x, y, 0) = static_cast<std::uint8_t>(std::min(v, 255));
            map.at(x, y, 1) = static_cast<std::uint8_t>(std::clamp(v - 255, 0, 255));
            map.at(x, y, 2) = static_cast<std::uint8_t>(std::clamp(v - 510, 0, 255));
        }
    }
    return map;
}

Image8 visiblyAltered(const Image8& image) {
    Image8 altered = image;
    const int x0 = image.width / 4;
    const int y0 = image.height / 4;
    for (int y = y0; y < y0 + image.height / 4; ++y) {
        for (int x = x0; x < x0 + image.width / 4; ++x) {
            for (int c = 0; c < image.channels; ++c) {
                altered.at(x, y, c) = static_cast<std::uint8_t>(255 - image.at(x, y, c));
            }
        }
    }
    return altered;
}

} // namespace t10::test
