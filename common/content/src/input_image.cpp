// Loading the --input HDR image: the limits come from the GL context and from /proc/meminfo, so a
// 20000 x 20000 EXR is refused from its header in milliseconds instead of failing minutes and
// gigabytes later at an incomplete framebuffer.
#include "t10/input_image.hpp"

#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/gl.hpp"

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>

namespace t10 {

namespace {

// MemAvailable in bytes, or 0 when /proc/meminfo cannot tell (then no memory limit applies).
std::uint64_t availableMemory() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024u;
    return 0;
}

} // namespace

ExrLimits renderLimits() {
    ExrLimits limits;
    GLint texture = 0;
    GLint renderbuffer = 0;
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const std::pair<GLint, const char*> candidates[] = {{texture, "GL_MAX_TEXTURE_SIZE"},
                                                        {renderbuffer, "GL_MAX_RENDERBUFFER_SIZE"},
                                                        {viewport[0], "GL_MAX_VIEWPORT_DIMS width"},
                                                        {viewport[1], "GL_MAX_VIEWPORT_DIMS height"}};
    for (const auto& [value, name] : candidates) {
        if (value > 0 && value < limits.maxSide) {
            limits.maxSide = value;
            limits.maxSideReason = std::string(name) + " of this GL context";
        }
    }
    if (const std::uint64_t bytes = availableMemory(); bytes > 0) {
        limits.maxPixels = bytes / kRenderBytesPerPixel;
        limits.maxPixelsReason = "rendering needs about " + std::to_string(kRenderBytesPerPixel) +
                                 " bytes per pixel and " + std::to_string(bytes >> 20) +
                                 " MiB of memory are available";
    }
    return limits;
}

ImageF loadInputImage(const std::string& path, bool keepNonFinite, std::ostream& warnings) {
    ImageF image = readExr(path, renderLimits());
    // One rule for every size (--size, --resize-sequence, --input): sides from 2, because the bloom
    // texture has two mipmap levels and a side of 1 has only one.
    if (image.width < contract::kMinFramebufferSide || image.height < contract::kMinFramebufferSide)
        throw Error(path + ": the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    "; each side must be at least " + std::to_string(contract::kMinFramebufferSide) +
                    " (the bloom texture needs two mipmap levels)");
    if (!keepNonFinite) {
        if (const std::size_t count = clampNonFinite(image, kHalfMax); count > 0)
            warnings << "warning: " << path << ": " << count << (count == 1 ? " pixel holds" : " pixels hold")
                     << " NaN or infinity; +infinity is read as " << kHalfMax
                     << " (the largest half float), NaN and -infinity as 0\n";
    }
    return image;
}

} // namespace t10
