#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "popup/model/result.hpp"

namespace popup {

/// An 8-bit RGBA image: rows from top to bottom, 4 bytes per pixel, straight (not premultiplied)
/// alpha. Pixel (column x, row y) starts at byte 4 * (y * width + x).
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;

    const std::uint8_t* at(int x, int y) const { return &pixels[4 * (size_t(y) * width + x)]; }
    std::uint8_t* at(int x, int y) { return &pixels[4 * (size_t(y) * width + x)]; }
};

/// The largest texture decoded (width × height), so a corrupt header cannot ask for gigabytes.
constexpr long long kMaxTexturePixels = 1LL << 27;

/// Decodes a PNG (libpng) or JPEG (libjpeg) image held in memory, recognised by its signature;
/// `name` says what it is in messages. Fails with unreadable_model naming `name` and the
/// decoder's reason for anything else, or for more than kMaxTexturePixels pixels.
Result<RgbaImage> decode_image(const std::string& bytes, const std::string& name);

/// Reads and decodes the image file at `path` (as decode_image).
Result<RgbaImage> read_image(const std::string& path);

} // namespace popup
