#include "popup/input/model_texture.hpp"

#include <filesystem>

namespace popup {

namespace {

std::string model_name(const ModelMesh& mesh)
{
    return mesh.source.empty() ? std::string("model") : mesh.source;
}

/// Embedded raw texels, already RGBA8 row by row (load_model turns assimp's BGRA aiTexel round).
Result<RgbaImage> raw_texels(const ModelMesh& mesh, const std::string& name)
{
    Result<RgbaImage> r;
    const long long width = mesh.texture_width, height = mesh.texture_height;
    if (height <= 0 || width * height > kMaxTexturePixels) {
        r.fail(DiagnosticCode::unreadable_texture,
               "texture " + name + ": " + std::to_string(width) + " x " + std::to_string(height) +
                   " texels, must be at least 1 x 1 and at most " +
                   std::to_string(kMaxTexturePixels) + " texels");
        return r;
    }
    if (mesh.texture_bytes.size() != size_t(4 * width * height)) {
        r.fail(DiagnosticCode::unreadable_texture,
               "texture " + name + ": " + std::to_string(mesh.texture_bytes.size()) +
                   " bytes for " + std::to_string(width) + " x " + std::to_string(height) +
                   " texels, must be 4 (RGBA) per texel");
        return r;
    }
    r.value.width = int(width);
    r.value.height = int(height);
    r.value.pixels.assign(mesh.texture_bytes.begin(), mesh.texture_bytes.end());
    return r;
}

} // namespace

std::string texture_file(const ModelMesh& mesh)
{
    namespace fs = std::filesystem;
    const fs::path given(mesh.texture);
    std::error_code ignored;
    if (given.is_absolute() || fs::exists(given, ignored) || mesh.source.empty())
        return mesh.texture;
    const fs::path beside = fs::path(mesh.source).parent_path() / given;
    return fs::exists(beside, ignored) ? beside.string() : mesh.texture;
}

Result<RgbaImage> read_model_texture(const ModelMesh& mesh)
{
    Result<RgbaImage> r;
    const bool embedded = !mesh.texture_bytes.empty() || mesh.texture_width > 0;
    if (mesh.texture.empty() && !embedded) {
        r.fail(DiagnosticCode::unreadable_texture, model_name(mesh) + ": has no texture");
        return r;
    }
    const std::string format = mesh.texture_format.empty() ? "" : " " + mesh.texture_format;
    const std::string name =
        embedded ? (mesh.texture.empty() ? "" : mesh.texture + " ") + "(embedded" + format + ")"
                 : texture_file(mesh);
    if (mesh.texture_width > 0)
        r = raw_texels(mesh, name);
    else if (embedded)
        r = decode_image(std::string(mesh.texture_bytes.begin(), mesh.texture_bytes.end()), name);
    else
        r = read_image(name);
    for (Diagnostic& d : r.diagnostics)
        d.message = model_name(mesh) + ": " + d.message;
    return r;
}

} // namespace popup
