// A model's texture (read_model_texture) and what load_model makes of the textured models
// tools/make_textured_models.py wrote into tests/data/textures: files beside the model, an
// embedded PNG in a GLB, raw texels, and an unreadable_texture warning naming the texture and
// the model when the image is missing or broken (the model still loads).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "popup/input/load_model.hpp"
#include "popup/input/model_texture.hpp"
#include "texture_fixtures.hpp"

namespace fs = std::filesystem;
using namespace popup;

namespace {

using namespace texture_fixtures;

/// The RGB make_textured_models painted on the named block.
std::array<int, 3> block(const std::string& name)
{
    const auto blocks = expected()["blocks"];
    return blocks[name].get<std::array<int, 3>>();
}

std::array<int, 3> rgb(const RgbaImage& image, int x, int y)
{
    const std::uint8_t* p = image.at(x, y);
    return {p[0], p[1], p[2]};
}

/// The four blocks of the 32 x 16 texture at their centres, the right way up.
void expect_blocks(const RgbaImage& image, const std::string& what)
{
    ASSERT_EQ(image.width, 32) << what;
    ASSERT_EQ(image.height, 16) << what;
    EXPECT_EQ(rgb(image, 8, 4), block("top_left")) << what;
    EXPECT_EQ(rgb(image, 24, 4), block("top_right")) << what;
    EXPECT_EQ(rgb(image, 8, 12), block("bottom_left")) << what;
    EXPECT_EQ(rgb(image, 24, 12), block("bottom_right")) << what;
}

} // namespace

TEST(ModelTexture, AFileIsFoundBesideTheModel)
{
    ModelMesh mesh;
    mesh.source = kFolder + "cube_tga.obj";
    mesh.texture = "texture.tga";
    EXPECT_EQ(fs::path(texture_file(mesh)), fs::path(kFolder) / "texture.tga");
    const Result<RgbaImage> image = read_model_texture(mesh);
    ASSERT_TRUE(image.ok) << image.diagnostics.front().message;
    expect_blocks(image.value, "texture.tga beside the model");
    mesh.texture = fs::absolute(kFolder + "texture.bmp").string(); // absolute: as given
    EXPECT_EQ(texture_file(mesh), mesh.texture);
    expect_blocks(read_model_texture(mesh).value, "texture.bmp");
}

TEST(ModelTexture, EmbeddedBytesAndRawTexelsAreDecodedWithoutAFile)
{
    ModelMesh mesh;
    mesh.source = "inline.glb";
    mesh.texture = "*0";
    const std::string png = bytes_of(kFolder + "texture.png");
    mesh.texture_bytes.assign(png.begin(), png.end());
    mesh.texture_format = "png";
    const Result<RgbaImage> embedded = read_model_texture(mesh);
    ASSERT_TRUE(embedded.ok) << embedded.diagnostics.front().message;
    expect_blocks(embedded.value, "embedded PNG");

    // Raw texels (assimp's uncompressed aiTexture, turned RGBA by load_model): 2 x 1.
    mesh.texture_bytes = {10, 20, 30, 255, 200, 100, 50, 128};
    mesh.texture_format = "rgba8888";
    mesh.texture_width = 2;
    mesh.texture_height = 1;
    const Result<RgbaImage> raw = read_model_texture(mesh);
    ASSERT_TRUE(raw.ok) << raw.diagnostics.front().message;
    EXPECT_EQ(raw.value.width, 2);
    EXPECT_EQ(raw.value.height, 1);
    EXPECT_EQ(raw.value.pixels, mesh.texture_bytes);
    mesh.texture_bytes.pop_back();
    EXPECT_TRUE(has(read_model_texture(mesh).diagnostics, DiagnosticCode::unreadable_texture,
                    "inline.glb: texture *0 (embedded rgba8888): 7 bytes for 2 x 1 texels, must "
                    "be 4 (RGBA) per texel"));
    mesh.texture_height = 0;
    EXPECT_TRUE(has(read_model_texture(mesh).diagnostics, DiagnosticCode::unreadable_texture,
                    "2 x 0 texels, must be at least 1 x 1"));

    mesh = ModelMesh{};
    mesh.source = "inline.glb";
    mesh.texture = "*0";
    mesh.texture_bytes = {'n', 'o', 'p', 'e'};
    mesh.texture_format = "jpg";
    EXPECT_TRUE(has(read_model_texture(mesh).diagnostics, DiagnosticCode::unreadable_texture,
                    "inline.glb: texture *0 (embedded jpg): not an image in a format read here"));
}

TEST(ModelTexture, AMissingTextureNamesTheModelAndTheFile)
{
    ModelMesh mesh;
    mesh.source = "/models/house.obj";
    mesh.texture = "/models/paint.tga";
    const Result<RgbaImage> missing = read_model_texture(mesh);
    EXPECT_FALSE(missing.ok);
    EXPECT_TRUE(has(missing.diagnostics, DiagnosticCode::unreadable_texture,
                    "/models/house.obj: texture /models/paint.tga: cannot open the file"));
    mesh.texture.clear();
    EXPECT_TRUE(has(read_model_texture(mesh).diagnostics, DiagnosticCode::unreadable_texture,
                    "/models/house.obj: has no texture"));
}

TEST(ModelTexture, LoadModelReadsFileAndEmbeddedTexturesSilently)
{
    for (const char* name : {"cube_tga.obj", "cube_bmp.obj", "cube_png.glb"}) {
        const Result<ModelMesh> read = load_model(kFolder + name);
        ASSERT_TRUE(read.ok) << name << ": " << read.diagnostics.front().message;
        EXPECT_TRUE(read.diagnostics.empty()) << name << ": " << read.diagnostics.front().message;
        const ModelMesh& mesh = read.value;
        EXPECT_EQ(mesh.triangles.size(), 12u) << name;
        ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size()) << name;
        const Result<RgbaImage> image = read_model_texture(mesh);
        ASSERT_TRUE(image.ok) << name;
        expect_blocks(image.value, name);
    }
    const ModelMesh glb = load_model(kFolder + "cube_png.glb").value;
    EXPECT_EQ(glb.texture, "*0");
    EXPECT_EQ(glb.texture_format, "png");
    const std::string png = bytes_of(kFolder + "texture.png");
    EXPECT_EQ(std::string(glb.texture_bytes.begin(), glb.texture_bytes.end()), png);
    const ModelMesh obj = load_model(kFolder + "cube_tga.obj").value;
    EXPECT_EQ(fs::path(obj.texture), (fs::path(kFolder) / "texture.tga").lexically_normal());
    EXPECT_TRUE(obj.texture_bytes.empty());
}

TEST(ModelTexture, LoadModelWarnsOfAMissingOrBrokenTextureAndStillLoads)
{
    for (const auto& [name, texture, why] : std::vector<std::array<std::string, 3>>{
             {"cube_missing.obj", "missing.tga", "cannot open the file"},
             {"cube_corrupt.obj", "corrupt.png", "broken image data (stb_image: "}}) {
        const Result<ModelMesh> read = load_model(kFolder + name);
        ASSERT_TRUE(read.ok) << name;
        ASSERT_EQ(read.diagnostics.size(), 1u) << name;
        const Diagnostic& d = read.diagnostics.front();
        EXPECT_EQ(d.code, DiagnosticCode::unreadable_texture) << name;
        EXPECT_EQ(d.severity, Severity::warning) << name;
        const std::string model = kFolder + name;
        const std::string file = (fs::path(kFolder) / texture).lexically_normal().string();
        EXPECT_EQ(d.message.rfind(model + ": texture " + file + ": ", 0), 0u)
            << "the model first, then the texture: " << d.message;
        EXPECT_NE(d.message.find(why), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("; its artwork is the shaded base colour"), std::string::npos)
            << d.message;
        EXPECT_EQ(d.parameter, file);
        EXPECT_EQ(read.value.triangles.size(), 12u) << name;
        EXPECT_EQ(fs::path(read.value.texture), fs::path(file)) << "kept as the file names it";
    }
}
