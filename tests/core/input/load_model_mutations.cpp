#include "load_model_mutations.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include "popup/input/load_model.hpp"

namespace fs = std::filesystem;

namespace popup::fixtures {

namespace {

/// A tetrahedron with one colour per corner and texture coordinates, and a cuboid beside it,
/// each under its own node and material.
std::unique_ptr<aiScene> seed_scene()
{
    auto scene = std::make_unique<aiScene>();
    const std::vector<std::vector<aiVector3D>> corners = {
        {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}},
        {{20, 0, 0},
         {30, 0, 0},
         {20, 5, 0},
         {30, 5, 0},
         {20, 0, 8},
         {30, 0, 8},
         {20, 5, 8},
         {30, 5, 8}}};
    const std::vector<std::vector<std::array<unsigned, 3>>> faces = {
        {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}},
        {{0, 2, 3},
         {0, 3, 1},
         {4, 5, 7},
         {4, 7, 6},
         {0, 1, 5},
         {0, 5, 4},
         {2, 6, 7},
         {2, 7, 3},
         {0, 4, 6},
         {0, 6, 2},
         {1, 3, 7},
         {1, 7, 5}}};
    scene->mNumMeshes = scene->mNumMaterials = 2;
    scene->mMeshes = new aiMesh*[2];
    scene->mMaterials = new aiMaterial*[2];
    scene->mRootNode = new aiNode("root");
    scene->mRootNode->mNumChildren = 2;
    scene->mRootNode->mChildren = new aiNode*[2];
    for (unsigned m = 0; m < 2; ++m) {
        auto* mesh = new aiMesh;
        mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
        mesh->mMaterialIndex = m;
        mesh->mNumVertices = unsigned(corners[m].size());
        mesh->mVertices = new aiVector3D[mesh->mNumVertices];
        std::copy(corners[m].begin(), corners[m].end(), mesh->mVertices);
        if (m == 0) {
            mesh->mColors[0] =
                new aiColor4D[4]{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
            mesh->mTextureCoords[0] = new aiVector3D[4]{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
            mesh->mNumUVComponents[0] = 2;
        }
        mesh->mNumFaces = unsigned(faces[m].size());
        mesh->mFaces = new aiFace[mesh->mNumFaces];
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            mesh->mFaces[f].mNumIndices = 3;
            mesh->mFaces[f].mIndices = new unsigned[3];
            std::copy(faces[m][f].begin(), faces[m][f].end(), mesh->mFaces[f].mIndices);
        }
        scene->mMeshes[m] = mesh;
        auto* material = new aiMaterial;
        const aiString name("paint" + std::to_string(m));
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor4D diffuse(0.2f * float(m + 1), 0.4f, 0.6f, 1.0f);
        material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
        scene->mMaterials[m] = material;
        auto* node = new aiNode("part" + std::to_string(m));
        node->mParent = scene->mRootNode;
        node->mNumMeshes = 1;
        node->mMeshes = new unsigned[1]{m};
        scene->mRootNode->mChildren[m] = node;
    }
    return scene;
}

std::string bytes_of(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

/// Where a number starts and ends in `text` near `at` (none: {at, at}).
std::pair<size_t, size_t> number_near(const std::string& text, size_t at)
{
    auto is_number = [](char c) {
        return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e';
    };
    size_t begin = at;
    while (begin < text.size() && !is_number(text[begin]))
        ++begin;
    size_t end = begin;
    while (end < text.size() && is_number(text[end]))
        ++end;
    return {begin, end};
}

/// One mutation of `bytes`, chosen and placed by `random`.
std::string mutate(std::string bytes, const std::vector<std::string>& others,
                   std::mt19937_64& random)
{
    static const char* const tokens[] = {
        "nan",    "-nan", "NaN", "inf",        "-inf", "1e39",       "-1e400",
        "1e-400", "0",    "-0",  "4294967295", "-1",   "2147483648", "99999999999999999999",
        "",       " ",    "\n",  "#",          "/",    "0x7fffffff", "1.#QNAN"};
    auto pick = [&](size_t n) { return n ? size_t(random() % n) : size_t(0); };
    const int rounds = 1 + int(random() % 4);
    for (int r = 0; r < rounds; ++r) {
        const size_t at = pick(bytes.size() + 1);
        switch (random() % 8) {
        case 0: // flip one bit
            if (!bytes.empty())
                bytes[pick(bytes.size())] ^= char(1u << (random() % 8));
            break;
        case 1: // a random byte
            if (!bytes.empty())
                bytes[pick(bytes.size())] = char(random() & 0xff);
            break;
        case 2: // insert random bytes
            bytes.insert(at, std::string(1 + pick(8), char(random() & 0xff)));
            break;
        case 3: // delete a run
            bytes.erase(at, 1 + pick(64));
            break;
        case 4: // truncate
            bytes.resize(pick(bytes.size() + 1));
            break;
        case 5: { // duplicate a chunk elsewhere
            const size_t from = pick(bytes.size() + 1), length = pick(256);
            bytes.insert(pick(bytes.size() + 1), bytes.substr(from, length));
            break;
        }
        case 6: { // a number replaced by an awkward one
            const auto [begin, end] = number_near(bytes, at);
            bytes.replace(begin, end - begin, tokens[pick(std::size(tokens))]);
            break;
        }
        default: { // splice in a piece of another seed
            const std::string& other = others[pick(others.size())];
            const size_t from = pick(other.size() + 1);
            bytes.insert(at, other.substr(from, pick(512)));
            break;
        }
        }
    }
    return bytes;
}

/// Empty when `read` keeps load_model's contract for `file`, else why not.
std::string contract_broken(const Result<ModelMesh>& read, const fs::path& file)
{
    if (read.ok) {
        const ModelMesh& m = read.value;
        if (m.triangles.empty())
            return "a mesh without triangles";
        for (const Vec3& v : m.vertices)
            if (!v.allFinite())
                return "a mesh with a non-finite vertex";
        for (const auto& t : m.triangles)
            for (int k : t)
                if (k < 0 || k >= int(m.vertices.size()))
                    return "a triangle indexing vertex " + std::to_string(k);
        if (!(m.area() > 0.0))
            return "a mesh without area";
        return {};
    }
    if (read.diagnostics.empty())
        return "failed without a diagnostic";
    const Diagnostic& d = read.diagnostics.front();
    const DiagnosticCode named[] = {DiagnosticCode::unreadable_model, DiagnosticCode::empty_model,
                                    DiagnosticCode::non_finite_model,
                                    DiagnosticCode::degenerate_model,
                                    DiagnosticCode::bad_model_size};
    if (std::find(std::begin(named), std::end(named), d.code) == std::end(named))
        return "unexpected code " + std::to_string(int(d.code)) + ": " + d.message;
    if (d.message.find(file.string()) == std::string::npos)
        return "the error does not name the file: " + d.message;
    return {};
}

} // namespace

std::vector<fs::path> write_seed_models(const fs::path& dir)
{
    fs::create_directories(dir);
    const auto scene = seed_scene();
    Assimp::Exporter exporter;
    std::vector<fs::path> seeds;
    const std::pair<const char*, const char*> formats[] = {
        {"obj", "obj"},    {"stl", "stl"},  {"stlb", "stl"},    {"ply", "ply"}, {"plyb", "ply"},
        {"gltf2", "gltf"}, {"glb2", "glb"}, {"collada", "dae"}, {"3mf", "3mf"}, {"fbx", "fbx"}};
    for (const auto& [id, extension] : formats) {
        const fs::path file = dir / (std::string("seed_") + id + "." + extension);
        if (exporter.Export(scene.get(), id, file.string()) == AI_SUCCESS)
            seeds.push_back(file);
    }
    const fs::path off = dir / "seed_hand.off";
    std::ofstream(off) << "OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n"
                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    seeds.push_back(off);
    return seeds;
}

MutationRun mutate_and_load(const std::vector<fs::path>& seeds, int iterations, std::uint64_t seed,
                            const fs::path& dir, double timeout_s)
{
    fs::create_directories(dir);
    std::vector<std::string> contents;
    for (const fs::path& s : seeds)
        contents.push_back(bytes_of(s));
    std::mt19937_64 random(seed);
    MutationRun run;
    for (int i = 0; i < iterations && !seeds.empty(); ++i) {
        const size_t which = size_t(random() % seeds.size());
        const fs::path file =
            dir / ("mutant_" + std::to_string(i) + seeds[which].extension().string());
        std::ofstream(file, std::ios::binary) << mutate(contents[which], contents, random);
        // Mutants sit beside the seeds, so a glTF still finds its buffer file.
        const auto start = std::chrono::steady_clock::now();
        const Result<ModelMesh> read = load_model(file.string(), LoadModelOptions{timeout_s});
        run.slowest_s = std::max(
            run.slowest_s,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        ++run.reads;
        ++(read.ok ? run.meshes : run.errors);
        if (!read.ok &&
            read.diagnostics.front().message.find("did not finish") != std::string::npos)
            ++run.timeouts;
        const std::string why = contract_broken(read, file);
        if (why.empty())
            fs::remove(file);
        else
            run.broken.push_back(file.string() + ": " + why);
    }
    return run;
}

} // namespace popup::fixtures
