#include "popup/input/load_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "child_process.hpp"
#include "model_mesh_bytes.hpp"
#include "popup/input/model_texture.hpp"
#include "text_coordinates.hpp"

namespace popup {

namespace {

namespace fs = std::filesystem;

Vec3 rgb(const aiColor4D& c)
{
    return Vec3(c.r, c.g, c.b).cwiseMax(0.0).cwiseMin(1.0);
}

/// The material's base colour (glTF's PBR factor) or else its diffuse colour; grey without either.
Vec3 material_colour(const aiMaterial* material)
{
    aiColor4D c;
    if (material && aiGetMaterialColor(material, AI_MATKEY_BASE_COLOR, &c) == AI_SUCCESS)
        return rgb(c);
    if (material && aiGetMaterialColor(material, AI_MATKEY_COLOR_DIFFUSE, &c) == AI_SUCCESS)
        return rgb(c);
    return Vec3(0.8, 0.8, 0.8);
}

/// The material's base-colour texture, else its diffuse one, as written in the file ("" if none).
std::string material_texture(const aiMaterial* material)
{
    if (!material)
        return {};
    aiString path;
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE})
        if (material->GetTextureCount(type) > 0 &&
            material->GetTexture(type, 0, &path) == AI_SUCCESS && path.length > 0)
            return path.C_Str();
    return {};
}

double mesh_area(const aiMesh* mesh)
{
    double area = 0.0;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        if (face.mNumIndices != 3)
            continue;
        const aiVector3D a = mesh->mVertices[face.mIndices[0]];
        const aiVector3D e1 = mesh->mVertices[face.mIndices[1]] - a;
        const aiVector3D e2 = mesh->mVertices[face.mIndices[2]] - a;
        area += 0.5 * (e1 ^ e2).Length();
    }
    return area;
}

/// Fills the mesh's texture fields from the scene: an embedded image keeps its bytes, a file
/// is named relative to the model's folder.
void attach_texture(const aiScene* scene, const std::string& model_path, const std::string& written,
                    ModelMesh& mesh)
{
    if (const aiTexture* embedded = scene->GetEmbeddedTexture(written.c_str())) {
        mesh.texture = written;
        const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
        if (embedded->mHeight == 0) { // a compressed file (png, jpg) of mWidth bytes
            mesh.texture_bytes.assign(bytes, bytes + embedded->mWidth);
            mesh.texture_format = embedded->achFormatHint;
        } else { // raw aiTexel (BGRA) texels
            mesh.texture_width = int(embedded->mWidth);
            mesh.texture_height = int(embedded->mHeight);
            mesh.texture_format = "rgba8888";
            const size_t n = size_t(embedded->mWidth) * embedded->mHeight;
            mesh.texture_bytes.reserve(4 * n);
            for (size_t i = 0; i < n; ++i) {
                const aiTexel& t = embedded->pcData[i];
                mesh.texture_bytes.insert(mesh.texture_bytes.end(), {t.r, t.g, t.b, t.a});
            }
        }
        return;
    }
    fs::path texture(written);
    if (texture.is_relative())
        texture = fs::path(model_path).parent_path() / texture;
    mesh.texture = texture.lexically_normal().string();
}

/// Removes faces without corners or with a corner index out of range (a truncated or odd file:
/// assimp 5.2's binary PLY reader gives corner-less faces) and sets each mesh's primitive types
/// from what remains, which the triangulation step trusts.
void drop_broken_faces(aiScene* scene)
{
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        aiMesh* mesh = scene->mMeshes[m];
        if (!mesh || !mesh->mFaces)
            continue;
        unsigned kept = 0, types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            aiFace& face = mesh->mFaces[f];
            bool usable = face.mNumIndices > 0 && face.mIndices;
            for (unsigned k = 0; usable && k < face.mNumIndices; ++k)
                usable = face.mIndices[k] < mesh->mNumVertices;
            if (!usable)
                continue;
            types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
                     : face.mNumIndices == 2 ? aiPrimitiveType_LINE
                     : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                             : aiPrimitiveType_POLYGON;
            if (kept != f)
                std::swap(mesh->mFaces[kept], face); // aiFace frees its indices itself
            ++kept;
        }
        mesh->mNumFaces =
            kept; // the dropped faces stay allocated past the end until the scene goes
        mesh->mPrimitiveTypes = types;
    }
}

/// Reads the file into `mesh`; returns why not ("" when read). Runs in the child process.
std::string read_with_assimp(const std::string& path, ModelMesh& mesh)
{
    Assimp::Importer importer;
    // Points and lines carry no surface: drop them rather than fail on them.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // A ModelMesh has no normals: drop them first, so corners split by face normals (STL) join.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                                aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS);
    const unsigned steps = aiProcess_RemoveComponent | aiProcess_Triangulate |
                           aiProcess_PreTransformVertices | aiProcess_SortByPType |
                           aiProcess_ValidateDataStructure;
    const aiScene* scene = nullptr;
    try {
        // Read first, then drop faces no step can handle, then post-process: assimp's steps
        // abort the process (ai_assert) on some faces its own readers deliver.
        scene = importer.ReadFile(path, 0);
        if (scene) {
            drop_broken_faces(const_cast<aiScene*>(scene));
            scene = importer.ApplyPostProcessing(steps);
        }
    } catch (const std::exception& e) {
        return (std::string("assimp failed: ") + e.what());
    }
    if (!scene)
        return (std::string("assimp could not read it: ") + importer.GetErrorString());
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        return ("assimp read an incomplete scene (" + std::string(importer.GetErrorString()) + ")");

    mesh.source = path;
    std::vector<const aiMesh*> parts;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        if (scene->mMeshes[m] && (scene->mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            parts.push_back(scene->mMeshes[m]);
    auto material_of = [&](const aiMesh* part) -> const aiMaterial* {
        return part->mMaterialIndex < scene->mNumMaterials ? scene->mMaterials[part->mMaterialIndex]
                                                           : nullptr;
    };

    // Which appearance the merged mesh carries: the first texture any material uses; vertex
    // colours when a part has them or the parts' materials differ in colour.
    std::string texture;
    bool any_colours = false, any_uvs = false;
    std::vector<std::tuple<double, double, double>> distinct;
    double largest = -1.0;
    for (const aiMesh* part : parts) {
        const aiMaterial* material = material_of(part);
        if (texture.empty())
            texture = material_texture(material);
        any_colours = any_colours || part->HasVertexColors(0);
        any_uvs = any_uvs || part->HasTextureCoords(0);
        const Vec3 c = material_colour(material);
        const auto key = std::make_tuple(c.x(), c.y(), c.z());
        if (std::find(distinct.begin(), distinct.end(), key) == distinct.end())
            distinct.push_back(key);
        const double area = mesh_area(part);
        if (area > largest) {
            largest = area;
            mesh.base_colour = c;
        }
    }
    const bool keep_colours = any_colours || distinct.size() > 1;
    if (!texture.empty())
        attach_texture(scene, path, texture, mesh);

    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const aiMesh* part : parts) {
        const aiMaterial* material = material_of(part);
        const Vec3 colour = material_colour(material);
        // Texture coordinates count only where they index `texture` (or when nothing is textured).
        const bool uv_here =
            part->HasTextureCoords(0) && (texture.empty() || material_texture(material) == texture);
        // Corners with the same position, colour and texture coordinate become one vertex.
        // Done here, not by aiProcess_JoinIdenticalVertices: assimp 5.2's step joins an OBJ's
        // corners of different vertex colours (a red and a blue face sharing an edge came back
        // with one colour).
        std::map<std::array<std::uint64_t, 8>, int> joined;
        std::vector<int> index_of(part->mNumVertices);
        for (unsigned v = 0; v < part->mNumVertices; ++v) {
            const aiVector3D& p = part->mVertices[v];
            const Vec3 c = keep_colours
                               ? (part->HasVertexColors(0) ? rgb(part->mColors[0][v]) : colour)
                               : Vec3::Zero();
            const Vec2 uv = !any_uvs ? Vec2::Zero()
                            : uv_here
                                ? Vec2(part->mTextureCoords[0][v].x, part->mTextureCoords[0][v].y)
                                : Vec2(nan, nan);
            const std::array<double, 8> values{p.x, p.y, p.z, c.x(), c.y(), c.z(), uv.x(), uv.y()};
            std::array<std::uint64_t, 8> key{};
            std::memcpy(key.data(), values.data(), sizeof(values)); // bits: NaN equals itself
            const auto [at, added] = joined.emplace(key, int(mesh.vertices.size()));
            index_of[v] = at->second;
            if (!added)
                continue;
            mesh.vertices.emplace_back(p.x, p.y, p.z);
            if (keep_colours)
                mesh.colours.push_back(c);
            if (any_uvs)
                mesh.uvs.push_back(uv);
        }
        for (unsigned f = 0; f < part->mNumFaces; ++f) {
            const aiFace& face = part->mFaces[f];
            if (face.mNumIndices == 3)
                mesh.triangles.push_back({index_of[face.mIndices[0]], index_of[face.mIndices[1]],
                                          index_of[face.mIndices[2]]});
        }
    }
    return {};
}

/// Why the mesh's texture cannot be shown ("" when it decodes or there is none). Decoded here,
/// in the child, so a decoder crash on a hostile image ends only the reader.
std::string texture_problem(const ModelMesh& mesh)
{
    if (mesh.texture.empty())
        return {};
    const Result<RgbaImage> image = read_model_texture(mesh);
    if (image.ok)
        return {};
    std::string why;
    for (const Diagnostic& d : image.diagnostics)
        why += (why.empty() ? "" : "; ") + d.message;
    return why + (mesh.colours.empty() ? "; its artwork is the shaded base colour"
                                       : "; its artwork shows the vertex colours");
}

// The mesh crosses from the reading child to the caller as plain bytes: why not, the mesh, then
// why its texture cannot be shown.
std::string encode(const std::string& why, const ModelMesh& mesh, const std::string& texture)
{
    ByteWriter w;
    w.put_text(why);
    put_mesh(w, mesh);
    w.put_text(texture);
    return w.bytes;
}

/// Reads the file in a child process (child_process.hpp). Returns why not ("" when read);
/// `texture_warning` says why the texture cannot be shown ("" when it can or there is none).
std::string read_isolated(const std::string& path, double timeout_s, ModelMesh& mesh,
                          std::string& texture_warning)
{
    std::string bytes;
    const std::string failed = run_in_child(
        [&] {
            ModelMesh read;
            std::string why, texture;
            try {
                why = read_with_assimp(path, read);
                if (why.empty())
                    texture = texture_problem(read);
            } catch (const std::exception& e) {
                why = std::string("assimp failed: ") + e.what();
            }
            return encode(why, read, texture);
        },
        timeout_s, bytes);
    if (!failed.empty())
        return failed;
    ByteReader r{bytes};
    const std::string why = r.get_text();
    get_mesh(r, mesh);
    texture_warning = r.get_text();
    if (!r.whole())
        return "the reader process ended without a whole answer";
    return why;
}

} // namespace

Result<ModelMesh> load_model(const std::string& path, const LoadModelOptions& options)
{
    Result<ModelMesh> result;
    auto refuse = [&](const std::string& why) {
        result.fail(DiagnosticCode::unreadable_model, "model file " + path + ": " + why,
                    about_parameter(path));
        return result;
    };
    std::error_code error;
    if (path.empty())
        return refuse("no path given");
    if (!fs::exists(path, error))
        return refuse("no such file");
    if (!fs::is_regular_file(path, error))
        return refuse("not a regular file");
    if (!(options.timeout_s > 0.0))
        return refuse("timeout_s = " + std::to_string(options.timeout_s) + ", must be > 0");

    // Before assimp, which reads some spellings of NaN in text files as finite numbers.
    if (const auto bad = find_non_finite_coordinate(path)) {
        result.fail(
            DiagnosticCode::non_finite_model,
            "model file " + path + ": vertex " + std::to_string(bad->vertex) + " (line " +
                std::to_string(bad->line) + ") has " + bad->axis + " = " + bad->token +
                ", coordinates must be finite numbers within single precision (|v| <= " + "3.4e38)",
            about_parameter(path));
        return result;
    }
    ModelMesh mesh;
    std::string texture_warning;
    const std::string why = read_isolated(path, options.timeout_s, mesh, texture_warning);
    if (!why.empty())
        return refuse(why);
    mesh.source = path;
    Result<ModelMesh> checked = check_model(std::move(mesh));
    if (checked.ok && !texture_warning.empty())
        checked.warn(DiagnosticCode::unreadable_texture, texture_warning,
                     about_parameter(checked.value.texture));
    return checked;
}

} // namespace popup
