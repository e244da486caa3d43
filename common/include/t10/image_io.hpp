// Reading and writing images: PNG (8-bit, stb), OpenEXR (RGBA half) and PFM (32-bit float, used
// for the numeric test dumps). Every function throws t10::Error naming the file on failure.
#pragma once
#include "t10/image.hpp"

#include <string>

namespace t10 {

// 8-bit grey, RGB or RGBA. The file's top row is the image's last row (row 0 is the bottom).
void writePng(const std::string& path, const Image8& image);
Image8 readPng(const std::string& path);

// RGBA half-float OpenEXR; 3-channel images get alpha 1.
void writeExr(const std::string& path, const ImageF& image);
// Always returns 4 channels.
ImageF readExr(const std::string& path);

// Portable float map ("Pf" grey or "PF" RGB, little-endian). PFM stores the bottom row first too.
void writePfm(const std::string& path, const ImageF& image);
ImageF readPfm(const std::string& path);

} // namespace t10
