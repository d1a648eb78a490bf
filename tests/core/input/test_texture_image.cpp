// decode_image / read_image (stb_image) against the images tools/make_textured_models.py wrote
// with Pillow into tests/data/textures: the texels at known places as written (within a few
// levels for JPEG), and named refusals of what is not an image.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "popup/input/texture_image.hpp"
#include "texture_fixtures.hpp"

using namespace popup;

namespace {

using namespace texture_fixtures;

/// Every probe texel of `image` is within the tolerance of what make_textured_models wrote.
void expect_texels(const RgbaImage& image, const nlohmann::json& written, const std::string& name)
{
    ASSERT_EQ(image.width, written["width"].get<int>()) << name;
    ASSERT_EQ(image.height, written["height"].get<int>()) << name;
    ASSERT_EQ(image.pixels.size(), size_t(4) * image.width * image.height) << name;
    const int tolerance = written["tolerance"];
    for (const auto& texel : written["texels"]) {
        const int x = texel[0], y = texel[1];
        const std::uint8_t* p = image.at(x, y);
        for (int k = 0; k < 4; ++k)
            EXPECT_LE(std::abs(int(p[k]) - texel[2 + k].get<int>()), tolerance)
                << name << " texel (" << x << ", " << y << ") channel " << k;
    }
}

} // namespace

TEST(TextureImage, EveryWrittenFormatDecodesToTheTexelsWritten)
{
    const nlohmann::json images = expected()["images"];
    // TGA uncompressed and RLE, BMP, PNG, JPEG, GIF, PPM.
    ASSERT_EQ(images.size(), 7u);
    int lossless = 0;
    for (const auto& [name, written] : images.items()) {
        const Result<RgbaImage> image = read_image(kFolder + name);
        ASSERT_TRUE(image.ok) << name << ": " << image.diagnostics.front().message;
        EXPECT_TRUE(image.diagnostics.empty()) << name;
        expect_texels(image.value, written, name);
        lossless += written["tolerance"] == 0;
    }
    EXPECT_EQ(lossless, 6); // all but the JPEG exactly
}

TEST(TextureImage, DecodesFromMemoryAsFromTheFile)
{
    const nlohmann::json written = expected()["images"]["texture_rle.tga"];
    const Result<RgbaImage> image = decode_image(bytes_of(kFolder + "texture_rle.tga"), "rle");
    ASSERT_TRUE(image.ok);
    expect_texels(image.value, written, "texture_rle.tga");
}

TEST(TextureImage, WhatIsNoImageIsNamedWithTheReason)
{
    EXPECT_TRUE(has(read_image("/nonexistent/paint.tga").diagnostics,
                    DiagnosticCode::unreadable_texture,
                    "texture /nonexistent/paint.tga: cannot open the file"));
    EXPECT_TRUE(has(read_image(kFolder).diagnostics, DiagnosticCode::unreadable_texture,
                    "cannot open the file"));
    EXPECT_TRUE(has(decode_image("", "empty.png").diagnostics, DiagnosticCode::unreadable_texture,
                    "texture empty.png: the file is empty"));
    const Result<RgbaImage> text = decode_image("plain words, no picture", "notes.tga");
    EXPECT_FALSE(text.ok);
    EXPECT_TRUE(has(text.diagnostics, DiagnosticCode::unreadable_texture,
                    "texture notes.tga: not an image in a format read here (23 bytes); textures "
                    "may be PNG, JPEG, TGA, BMP"));
    // A PNG signature with no chunks after it, and a PNG cut in half: stb_image says why.
    const Result<RgbaImage> corrupt = read_image(kFolder + "corrupt.png");
    EXPECT_TRUE(has(corrupt.diagnostics, DiagnosticCode::unreadable_texture,
                    "corrupt.png: broken image data (stb_image: "));
    const std::string png = bytes_of(kFolder + "texture.png");
    EXPECT_TRUE(has(decode_image(png.substr(0, png.size() / 2), "half.png").diagnostics,
                    DiagnosticCode::unreadable_texture, "half.png: broken image data"));
    const std::string jpeg = bytes_of(kFolder + "texture.jpg");
    // Cut before its frame header (SOF at byte 158): no size, refused by every stb_image. Cut
    // later, in the Huffman tables, Debian 13's stb_image decodes the missing rest as blank.
    EXPECT_FALSE(decode_image(jpeg.substr(0, 120), "cut.jpg").ok);
}

TEST(TextureImage, AHeaderAskingForTooManyPixelsIsRefusedBeforeDecoding)
{
    // An uncompressed 24-bit TGA header of 65535 x 65535 pixels and no pixels after it.
    std::string header(18, '\0');
    header[2] = 2;                                                  // true colour
    header[12] = header[13] = header[14] = header[15] = char(0xff); // width, height
    header[16] = 24;                                                // bits per pixel
    const Result<RgbaImage> image = decode_image(header, "huge.tga");
    EXPECT_FALSE(image.ok);
    EXPECT_TRUE(has(image.diagnostics, DiagnosticCode::unreadable_texture,
                    "texture huge.tga: 65535 x 65535 pixels, at most 134217728 pixels are read"));
}
