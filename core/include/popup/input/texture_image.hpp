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

/// The image formats decode_image reads, for messages and documentation.
extern const char* const kTextureFormats;

/// Decodes an image held in memory with stb_image (Debian's libstb): PNG (8 and 16 bits, any
/// colour type, interlaced), JPEG (baseline and progressive), TGA (uncompressed and RLE), BMP
/// (uncompressed), GIF (the first frame), PSD (the composite), HDR (tone mapped), PIC and PNM,
/// recognised by their content, never by a name. Grey and RGB images get alpha 255; 16-bit and
/// HDR images come down to 8 bits. `name` says what the image is in messages. Fails with
/// unreadable_texture naming `name` and stb_image's reason for anything else, for a truncated
/// or corrupt image stb_image notices, or for more than kMaxTexturePixels pixels. It does not
/// notice a truncated TGA, BMP or PNM: the missing pixels decode as black (or repeated) ones.
Result<RgbaImage> decode_image(const std::string& bytes, const std::string& name);

/// Reads and decodes the image file at `path` (as decode_image); unreadable_texture naming the
/// path when it cannot be opened.
Result<RgbaImage> read_image(const std::string& path);

} // namespace popup
