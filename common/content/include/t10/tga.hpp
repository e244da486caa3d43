// TGA loader: true-colour and grey images, raw and RLE (types 2, 3, 10, 11), 8/24/32 bits per pixel,
// either vertical origin. Malformed input gives an error naming the file and the fault, never a
// crash, an out-of-bounds read or an allocation before the size is validated.
#pragma once
#include "t10/image.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace t10 {

// The largest width or height accepted.
constexpr int kTgaMaxSide = 16384;

// Decodes a TGA held in memory into grey (1), RGB (3) or RGBA (4) channels, bottom row first, RGB
// order. Throws t10::Error("<name>: <fault>") on anything it cannot decode; `name` is only used in
// that message.
Image8 decodeTga(const std::uint8_t* bytes, std::size_t size, const std::string& name);
// Reads and decodes a file; a missing or unreadable file is an error like any other
// ("<path>: cannot open file: <reason>").
Image8 loadTga(const std::string& path);

} // namespace t10
