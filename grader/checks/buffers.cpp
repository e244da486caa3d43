// A case's buffers in memory; see buffers.hpp.
#include "checks/buffers.hpp"

#include "t10/error.hpp"

namespace t10::grade {

int CaseBuffers::levelCount(int unit) const {
    const auto at = units.find(unit);
    return at == units.end() ? 0 : static_cast<int>(at->second.size());
}

ImageF CaseBuffers::level(int unit, int levelIndex) const {
    if (levelIndex < 0 || levelIndex >= levelCount(unit)) {
        const std::string file = "unit" + std::to_string(unit) + "_level" + std::to_string(levelIndex) + ".pfm";
        throw Error(name + "/" + file + ": not written by the stage (is the texture bound to unit " + std::to_string(unit) + "?)");
    }
    const BufferLevel& found = units.at(unit)[static_cast<std::size_t>(levelIndex)];
    if (found.fault) std::rethrow_exception(found.fault);
    return found.image;
}

double gpuMappedKey(const CaseBuffers& buffers) {
    const int levels = buffers.luminanceLevels();
    if (levels == 0) throw Error(buffers.name + ": no luminance texture on unit 16 (steps 12-13)");
    const ImageF last = buffers.level(kLuminanceUnit, levels - 1);
    double sum = 0.0;
    for (int y = 0; y < last.height; ++y)
        for (int x = 0; x < last.width; ++x) sum += last.at(x, y, 0);
    return sum / (double(last.width) * double(last.height));
}

} // namespace t10::grade
