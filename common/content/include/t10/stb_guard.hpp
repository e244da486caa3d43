// What stb_image may be given: the checks both of its callers (image_io's readPng and the glTF
// loader's images) run on the bytes first. Debian 12's stb_image (2022) trusts a JPEG's Huffman
// table counts: a DHT segment whose 16 counts add up to more than 256 makes it write past its tables
// (found by fuzz/gltf; fixed upstream in 2.28), and it decodes formats (GIF, BMP, PSD, ...) that no
// caller here asks for.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace t10 {

// Nothing when `bytes` are a PNG, or a JPEG whose Huffman tables are all within 256 codes; else
// the fault in a few words ("not a PNG or JPEG file", "corrupt JPEG (...)").
std::optional<std::string> stbInputFault(const std::uint8_t* bytes, std::size_t size);

} // namespace t10
