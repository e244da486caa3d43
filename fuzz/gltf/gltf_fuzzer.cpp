// libFuzzer entry for the glTF loader: any bytes, as .gltf JSON or (with the "glTF" magic) as GLB.
// A t10::Error is the loader refusing the input, which is fine; anything else (a crash, a
// sanitizer report, another exception, more than 2 GiB, more than 10 s) is a finding. External
// files are not read, and the limits are lowered so that a legal but huge scene is not mistaken
// for unbounded memory.
#include "t10/error.hpp"
#include "t10/gltf_scene.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    t10::GltfLoadLimits limits;
    limits.allowExternalFiles = false;
    limits.maxTriangles = std::size_t(1) << 20;
    limits.maxVertices = std::size_t(1) << 21;
    limits.maxImageSide = 4096;
    limits.maxImagePixels = std::size_t(1) << 24;
    try {
        t10::loadGltfSceneFromMemory(data, size, "fuzz-input", "/nonexistent", limits);
    } catch (const t10::Error&) {
    }
    return 0;
}
