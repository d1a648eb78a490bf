#pragma once
#include <string>

#include "popup/input/model_mesh.hpp"
#include "popup/input/texture_image.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// The file a model's texture names: as given when it is absolute or exists, else beside the
/// model file (mesh.source), where assimp's relative paths start.
std::string texture_file(const ModelMesh& mesh);

/// The model's base-colour image (ModelMesh::texture): embedded bytes (a PNG or JPEG inside a
/// GLB or FBX) decoded, embedded raw texels (texture_width > 0) taken as they are, else the file
/// (texture_file) read; decode_image reads the formats. Fails with unreadable_texture naming the
/// model and the texture, and why: no texture, a missing file, bytes that are no image it reads,
/// raw texels not 4 bytes each for the size given.
Result<RgbaImage> read_model_texture(const ModelMesh& mesh);

} // namespace popup
