#include "popup/input/texture_image.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

#include <jpeglib.h>
#include <png.h>

namespace popup {

namespace {

bool starts_with(const std::string& bytes, const char* signature, size_t n)
{
    return bytes.size() >= n && std::memcmp(bytes.data(), signature, n) == 0;
}

Result<RgbaImage> too_large(const std::string& name, long long width, long long height)
{
    Result<RgbaImage> r;
    r.fail(DiagnosticCode::unreadable_model,
           "texture " + name + ": " + std::to_string(width) + " x " + std::to_string(height) +
               " pixels, at most " + std::to_string(kMaxTexturePixels) + " pixels are read");
    return r;
}

Result<RgbaImage> decode_png(const std::string& bytes, const std::string& name)
{
    Result<RgbaImage> r;
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
        r.fail(DiagnosticCode::unreadable_model,
               "texture " + name + ": not a readable PNG (" + png.message + ")");
        return r;
    }
    if (static_cast<long long>(png.width) * png.height > kMaxTexturePixels) {
        png_image_free(&png);
        return too_large(name, png.width, png.height);
    }
    png.format = PNG_FORMAT_RGBA;
    RgbaImage& image = r.value;
    image.width = int(png.width);
    image.height = int(png.height);
    image.pixels.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
        r.fail(DiagnosticCode::unreadable_model,
               "texture " + name + ": broken PNG data (" + png.message + ")");
        image = RgbaImage{};
    }
    return r;
}

// libjpeg reports errors through error_exit, which must not return: jump back to the caller.
struct JpegErrors {
    jpeg_error_mgr manager;
    std::jmp_buf back;
    char message[JMSG_LENGTH_MAX];
};

void jpeg_fail(j_common_ptr info)
{
    JpegErrors* errors = reinterpret_cast<JpegErrors*>(info->err);
    errors->manager.format_message(info, errors->message);
    std::longjmp(errors->back, 1);
}

// The decompressor and the output live on the heap, so nothing the jump skips needs destroying.
struct JpegDecoder {
    jpeg_decompress_struct info;
    JpegErrors errors;
    RgbaImage image;
};

Result<RgbaImage> decode_jpeg(const std::string& bytes, const std::string& name)
{
    Result<RgbaImage> r;
    auto decoder = std::make_unique<JpegDecoder>();
    JpegDecoder* d = decoder.get();
    d->info.err = jpeg_std_error(&d->errors.manager);
    d->errors.manager.error_exit = jpeg_fail;
    if (setjmp(d->errors.back)) {
        jpeg_destroy_decompress(&d->info);
        r.fail(DiagnosticCode::unreadable_model,
               "texture " + name + ": broken JPEG data (" + d->errors.message + ")");
        return r;
    }
    jpeg_create_decompress(&d->info);
    jpeg_mem_src(&d->info, reinterpret_cast<const unsigned char*>(bytes.data()),
                 static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&d->info, TRUE);
    if (static_cast<long long>(d->info.image_width) * d->info.image_height > kMaxTexturePixels) {
        const long long w = d->info.image_width, h = d->info.image_height;
        jpeg_destroy_decompress(&d->info);
        return too_large(name, w, h);
    }
    d->info.out_color_space = JCS_EXT_RGBA; // libjpeg-turbo: alpha filled with 255
    jpeg_start_decompress(&d->info);
    d->image.width = int(d->info.output_width);
    d->image.height = int(d->info.output_height);
    d->image.pixels.resize(size_t(4) * d->image.width * d->image.height);
    while (d->info.output_scanline < d->info.output_height) {
        JSAMPROW row =
            d->image.pixels.data() + size_t(4) * d->image.width * d->info.output_scanline;
        jpeg_read_scanlines(&d->info, &row, 1);
    }
    jpeg_finish_decompress(&d->info);
    jpeg_destroy_decompress(&d->info);
    r.value = std::move(d->image);
    return r;
}

} // namespace

Result<RgbaImage> decode_image(const std::string& bytes, const std::string& name)
{
    if (starts_with(bytes, "\x89PNG\r\n\x1a\n", 8))
        return decode_png(bytes, name);
    if (starts_with(bytes, "\xff\xd8\xff", 3))
        return decode_jpeg(bytes, name);
    Result<RgbaImage> r;
    r.fail(DiagnosticCode::unreadable_model, "texture " + name + ": neither PNG nor JPEG (" +
                                                 std::to_string(bytes.size()) +
                                                 " bytes); textures must be PNG or JPEG");
    return r;
}

Result<RgbaImage> read_image(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        Result<RgbaImage> r;
        r.fail(DiagnosticCode::unreadable_model, "texture " + path + ": cannot open the file");
        return r;
    }
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return decode_image(bytes.str(), path);
}

} // namespace popup
