// OpenEXR files in the browser build (compiled instead of exr_io.cpp, common/CMakeLists.txt): OpenEXR
// has no WebAssembly build, so no EXR file is read or written; each function refuses naming the file.
#include "t10/image_io.hpp"

#include "image_file.hpp"

namespace t10 {

namespace {
[[noreturn]] void noExr(const std::string& name) {
    image_file::fail(name, "EXR files are not available in the web build (OpenEXR has no WebAssembly build)");
}
} // namespace

void writeExr(const std::string& path, const ImageF&) { noExr(path); }
ImageF readExr(const std::string& path, const ExrLimits&) { noExr(path); }
ImageF decodeExr(const std::uint8_t*, std::size_t, const std::string& name, const ExrLimits&) { noExr(name); }

} // namespace t10
