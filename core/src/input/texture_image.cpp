#include "popup/input/texture_image.hpp"

#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <stb_image.h>

namespace popup {

const char* const kTextureFormats = "PNG, JPEG, TGA, BMP, GIF, PSD, HDR, PIC or PNM";

namespace {

Result<RgbaImage> unreadable(const std::string& name, const std::string& why)
{
    Result<RgbaImage> r;
    r.fail(DiagnosticCode::unreadable_texture, "texture " + name + ": " + why);
    return r;
}

/// stb_image's reason for the last failure on this thread (a short phrase such as "bad png sig").
std::string stb_reason()
{
    const char* reason = stbi_failure_reason();
    return reason ? reason : "no reason given";
}

} // namespace

Result<RgbaImage> decode_image(const std::string& bytes, const std::string& name)
{
    if (bytes.empty())
        return unreadable(name, "the file is empty");
    if (bytes.size() > size_t(INT_MAX))
        return unreadable(name, std::to_string(bytes.size()) + " bytes, at most " +
                                    std::to_string(INT_MAX) + " bytes are read");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(bytes.size());
    auto too_large = [&](long long width, long long height) {
        return unreadable(name, std::to_string(width) + " x " + std::to_string(height) +
                                    " pixels, at most " + std::to_string(kMaxTexturePixels) +
                                    " pixels are read");
    };
    // The header first, so its size is checked before the pixels are allocated. When stb_image
    // cannot read a header, decoding says why (its header readers leave only "unknown type").
    int width = 0, height = 0, channels = 0;
    const bool header = stbi_info_from_memory(data, length, &width, &height, &channels);
    if (header && static_cast<long long>(width) * height > kMaxTexturePixels)
        return too_large(width, height);
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(data, length, &width, &height, &channels, 4), stbi_image_free);
    if (!pixels) {
        const std::string reason = stb_reason();
        if (reason == "unknown image type")
            return unreadable(name, "not an image in a format read here (" +
                                        std::to_string(bytes.size()) + " bytes); textures may be " +
                                        kTextureFormats);
        return unreadable(name, "broken image data (stb_image: " + reason + ")");
    }
    if (static_cast<long long>(width) * height > kMaxTexturePixels)
        return too_large(width, height);
    Result<RgbaImage> r;
    r.value.width = width;
    r.value.height = height;
    r.value.pixels.assign(pixels.get(), pixels.get() + size_t(4) * width * height);
    return r;
}

Result<RgbaImage> read_image(const std::string& path)
{
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    std::ifstream file(path, std::ios::binary);
    if (error || !file)
        return unreadable(path, "cannot open the file");
    if (size > size_t(INT_MAX))
        return unreadable(path, std::to_string(size) + " bytes, at most " +
                                    std::to_string(INT_MAX) + " bytes are read");
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return decode_image(bytes.str(), path);
}

} // namespace popup
