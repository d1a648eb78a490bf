// load_animation: hand-written BVH files with known trajectories, and skinned scenes written by
// assimp's own Exporter (glTF 2, Collada) read back and compared with what was written.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "popup/motion/animation.hpp"

namespace fs = std::filesystem;
using namespace popup;

namespace {

fs::path scratch()
{
    const fs::path dir = fs::temp_directory_path() / "popup_load_animation";
    fs::create_directories(dir);
    return dir;
}

constexpr double deg = M_PI / 180.0;
constexpr double shoulder_rate = 10.0; // degrees per frame about z
constexpr double elbow_rate = -6.0;    // degrees per frame about y
const Vec3 shoulder_at(1.0, 2.0, 3.0);
constexpr double upper = 4.0, fore = 2.5;

/// A two-bone arm: the shoulder at (1, 2, 3) turns about z at 10°/frame, the elbow (4 along x)
/// about y at -6°/frame, the hand an end site 2.5 along x; 12 frames of 1/25 s.
std::string arm_bvh(int frames)
{
    std::ostringstream s;
    s << "HIERARCHY\nROOT Shoulder\n{\n  OFFSET 1 2 3\n"
         "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
         "  JOINT Elbow\n  {\n    OFFSET 4 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "    End Site\n    {\n      OFFSET 2.5 0 0\n    }\n  }\n}\n"
      << "MOTION\nFrames: " << frames << "\nFrame Time: 0.04\n";
    for (int f = 0; f < frames; ++f)
        s << "1 2 3 " << shoulder_rate * f << " 0 0 0 0 " << elbow_rate * f << "\n";
    return s.str();
}

std::string write(const std::string& name, const std::string& text)
{
    const fs::path path = scratch() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

/// hand(f) = shoulder + Rz(a)(upper x + Ry(b)(fore x)), a = 10° f, b = -6° f.
Vec3 analytic_hand(double f)
{
    const double a = shoulder_rate * f * deg, b = elbow_rate * f * deg;
    const Vec3 forearm(fore * std::cos(b), 0.0, -fore * std::sin(b)); // Ry(b) x
    const Vec3 local = Vec3(upper, 0, 0) + forearm;
    return shoulder_at + Vec3(std::cos(a) * local.x() - std::sin(a) * local.y(),
                              std::sin(a) * local.x() + std::cos(a) * local.y(), local.z());
}

int bone_named(const Animation& a, const std::string& name)
{
    for (size_t b = 0; b < a.bones.size(); ++b)
        if (a.bones[b].name == name)
            return int(b);
    return -1;
}

DiagnosticCode code_of(const Result<Animation>& r)
{
    EXPECT_FALSE(r.ok);
    return r.ok || r.diagnostics.empty() ? DiagnosticCode::bad_option : r.diagnostics[0].code;
}

// A skinned strip for the exporters: vertices at x = 0, 2, 4, 6, 8 and y = ±0.5; the upper bone
// (at the origin) holds x <= 2, the lower bone (at x = 4) x >= 6, the middle pair half each.
// At 0, 1 and 2 s: upper turns 0, 30°, 60° about z, lower 0, -20°, -40°.
struct Strip {
    std::vector<Vec3> vertices;
    std::vector<std::map<std::string, double>> weights;
};

Strip strip()
{
    Strip s;
    for (int i = 0; i < 5; ++i)
        for (double y : {-0.5, 0.5}) {
            s.vertices.emplace_back(2.0 * i, y, 0.0);
            if (i < 2)
                s.weights.push_back({{"Upper", 1.0}});
            else if (i == 2)
                s.weights.push_back({{"Upper", 0.5}, {"Lower", 0.5}});
            else
                s.weights.push_back({{"Lower", 1.0}});
        }
    return s;
}

aiQuaternion about_z(double degrees)
{
    return aiQuaternion(aiVector3D(0, 0, 1), float(degrees * deg));
}

/// The strip; keys at 0, 1 and 2 s, that is at ticks 0, tps and 2 tps.
std::unique_ptr<aiScene> strip_scene(bool animated, double ticks_per_second = 10.0)
{
    const Strip k = strip();
    auto scene = std::make_unique<aiScene>();
    auto* mesh = new aiMesh;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = unsigned(k.vertices.size());
    mesh->mVertices = new aiVector3D[k.vertices.size()];
    for (size_t v = 0; v < k.vertices.size(); ++v)
        mesh->mVertices[v] = aiVector3D(float(k.vertices[v].x()), float(k.vertices[v].y()),
                                        float(k.vertices[v].z()));
    mesh->mNumFaces = 8;
    mesh->mFaces = new aiFace[8];
    for (unsigned i = 0; i < 4; ++i)
        for (unsigned t = 0; t < 2; ++t) {
            aiFace& face = mesh->mFaces[2 * i + t];
            face.mNumIndices = 3;
            const unsigned a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
            face.mIndices = t == 0 ? new unsigned[3]{a, c, b} : new unsigned[3]{b, c, d};
        }
    mesh->mNumBones = 2;
    mesh->mBones = new aiBone*[2];
    const char* names[2] = {"Upper", "Lower"};
    for (int b = 0; b < 2; ++b) {
        auto* bone = new aiBone;
        bone->mName = names[b];
        aiMatrix4x4::Translation(aiVector3D(b == 0 ? 0.0f : -4.0f, 0, 0), bone->mOffsetMatrix);
        std::vector<aiVertexWeight> w;
        for (size_t v = 0; v < k.vertices.size(); ++v)
            if (k.weights[v].count(names[b]))
                w.emplace_back(unsigned(v), float(k.weights[v].at(names[b])));
        bone->mNumWeights = unsigned(w.size());
        bone->mWeights = new aiVertexWeight[w.size()];
        std::copy(w.begin(), w.end(), bone->mWeights);
        mesh->mBones[b] = bone;
    }
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh* [1] { mesh };
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial* [1] { new aiMaterial };
    aiString material_name("paper");
    scene->mMaterials[0]->AddProperty(&material_name, AI_MATKEY_NAME);

    auto* root = new aiNode("Scene");
    auto* body = new aiNode("Body");
    auto* upper = new aiNode("Upper");
    auto* lower = new aiNode("Lower");
    aiMatrix4x4::Translation(aiVector3D(4, 0, 0), lower->mTransformation);
    body->mNumMeshes = 1;
    body->mMeshes = new unsigned[1]{0};
    root->mNumChildren = 2;
    root->mChildren = new aiNode* [2] { body, upper };
    body->mParent = upper->mParent = root;
    upper->mNumChildren = 1;
    upper->mChildren = new aiNode* [1] { lower };
    lower->mParent = upper;
    scene->mRootNode = root;

    if (animated) {
        auto* clip = new aiAnimation;
        clip->mName = "wave";
        clip->mTicksPerSecond = ticks_per_second;
        clip->mDuration = 2.0 * ticks_per_second;
        clip->mNumChannels = 2;
        clip->mChannels = new aiNodeAnim*[2];
        const double angles[2][3] = {{0, 30, 60}, {0, -20, -40}};
        for (int b = 0; b < 2; ++b) {
            auto* ch = new aiNodeAnim;
            ch->mNodeName = names[b];
            ch->mNumPositionKeys = ch->mNumRotationKeys = ch->mNumScalingKeys = 3;
            ch->mPositionKeys = new aiVectorKey[3];
            ch->mRotationKeys = new aiQuatKey[3];
            ch->mScalingKeys = new aiVectorKey[3];
            for (int t = 0; t < 3; ++t) {
                ch->mPositionKeys[t] =
                    aiVectorKey(10.0 * t, aiVector3D(b == 0 ? 0.0f : 4.0f, 0, 0));
                ch->mRotationKeys[t] = aiQuatKey(ticks_per_second * t, about_z(angles[b][t]));
                ch->mScalingKeys[t] = aiVectorKey(ticks_per_second * t, aiVector3D(1, 1, 1));
            }
            clip->mChannels[b] = ch;
        }
        scene->mNumAnimations = 1;
        scene->mAnimations = new aiAnimation* [1] { clip };
    }
    return scene;
}

std::string export_scene(const aiScene& scene, const char* format, const std::string& name)
{
    const fs::path path = scratch() / name;
    Assimp::Exporter exporter;
    const aiReturn written = exporter.Export(&scene, format, path.string());
    EXPECT_EQ(written, aiReturn_SUCCESS) << format << ": " << exporter.GetErrorString();
    return path.string();
}

/// Reads back the strip; its last pose (2 s) is expected at `last_time_s`.
void expect_strip_read_back(const std::string& path, double last_time_s)
{
    const Result<Animation> r = load_animation(path);
    ASSERT_TRUE(r.ok) << path << ": " << r.diagnostics[0].message;
    const Animation& a = r.value;
    const int up = bone_named(a, "Upper"), low = bone_named(a, "Lower");
    ASSERT_GE(up, 0) << path;
    ASSERT_GE(low, 0) << path;
    EXPECT_EQ(a.bones[low].parent, up);
    // Every written vertex read back (some formats split or reorder), with its weights.
    const Strip k = strip();
    ASSERT_GE(a.mesh.vertices.size(), k.vertices.size());
    for (size_t w = 0; w < k.vertices.size(); ++w) {
        bool found = false;
        for (size_t v = 0; v < a.mesh.vertices.size(); ++v) {
            if ((a.mesh.vertices[v] - k.vertices[w]).norm() > 1e-5)
                continue;
            found = true;
            std::map<std::string, double> weights;
            for (const auto& [bone, weight] : a.skin[v])
                weights[a.bones[bone].name] += weight;
            ASSERT_EQ(weights.size(), k.weights[w].size()) << "vertex " << w;
            for (const auto& [name, weight] : k.weights[w])
                EXPECT_NEAR(weights[name], weight, 1e-6) << "vertex " << w << " bone " << name;
        }
        EXPECT_TRUE(found) << path << ": written vertex " << w << " not read back";
    }
    // At 2 s the upper bone has turned 60°, the lower 20° in all: vertex (8, 0.5) goes to
    // R(60°)(4, 0) + R(20°)(4, 0.5).
    ASSERT_EQ(a.frames(), 3) << path;
    EXPECT_NEAR(a.frame_times_s[2], last_time_s, 1e-6) << path;
    const int at = 2;
    const ModelMesh posed = posed_mesh(a, at);
    const Vec3 expected = Vec3(4 * std::cos(60 * deg), 4 * std::sin(60 * deg), 0) +
                          Vec3(4 * std::cos(20 * deg) - 0.5 * std::sin(20 * deg),
                               4 * std::sin(20 * deg) + 0.5 * std::cos(20 * deg), 0);
    double nearest = 1e9;
    for (const Vec3& p : posed.vertices)
        nearest = std::min(nearest, (p - expected).norm());
    EXPECT_LT(nearest, 1e-5) << path;
}

} // namespace

TEST(MotionLoadAnimation, BvhArmFollowsItsAnalyticTrajectory)
{
    const Result<Animation> r = load_animation(write("arm.bvh", arm_bvh(12)));
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    const Animation& a = r.value;
    ASSERT_EQ(a.frames(), 12);
    // BVH's frame time is kept as a float: 0.04 to 1e-9 relative.
    EXPECT_NEAR(a.frame_times_s[11], 11 * 0.04, 11 * 0.04 * 1e-7);
    const int shoulder = bone_named(a, "Shoulder"), elbow = bone_named(a, "Elbow");
    ASSERT_GE(shoulder, 0);
    ASSERT_GE(elbow, 0);
    EXPECT_EQ(a.bones[elbow].parent, shoulder);
    // The end site is a bone below the elbow, the chain's end effector.
    int hand = -1;
    for (size_t b = 0; b < a.bones.size(); ++b)
        if (a.bones[b].parent == elbow)
            hand = int(b);
    ASSERT_GE(hand, 0) << "no end-site bone";
    EXPECT_TRUE(a.mesh.vertices.empty());
    // assimp 5.2 keeps keys in float (ai_real): agreement to float precision of lengths ~7
    // (1.04e-6 measured over quarter frames).
    for (double f : {0.0, 1.0, 5.0, 11.0, 3.5})
        EXPECT_LT((forward_kinematics(a, f)[hand].translation() - analytic_hand(f)).norm(), 5e-6)
            << "frame " << f;
}

TEST(MotionLoadAnimation, SingleFrameAndBadFilesAreNamedErrors)
{
    EXPECT_EQ(code_of(load_animation(write("one.bvh", arm_bvh(1)))), DiagnosticCode::single_frame);
    // Truncated and garbage files: an error, and this process goes on.
    const std::string whole = arm_bvh(12);
    EXPECT_EQ(code_of(load_animation(write("cut.bvh", whole.substr(0, whole.size() / 3)))),
              DiagnosticCode::unreadable_model);
    std::string garbage;
    for (int i = 0; i < 4096; ++i)
        garbage.push_back(char((i * 7919 + 13) % 251));
    EXPECT_EQ(code_of(load_animation(write("garbage.fbx", garbage))),
              DiagnosticCode::unreadable_model);
    EXPECT_EQ(code_of(load_animation(write("garbage.glb", "glTF" + garbage))),
              DiagnosticCode::unreadable_model);
    EXPECT_EQ(code_of(load_animation((scratch() / "absent.bvh").string())),
              DiagnosticCode::unreadable_model);
    LoadAnimationOptions no_time;
    no_time.timeout_s = 0.0;
    EXPECT_EQ(code_of(load_animation(write("arm2.bvh", whole), no_time)),
              DiagnosticCode::unreadable_model);
}

TEST(MotionLoadAnimation, ARootWithOnlyPositionChannelsIsRefusedByName)
{
    // assimp 5.2 drops such a root's motion (measured: the root stays at the origin while its
    // frames move it 10 and 20 along x), so the file is refused, naming the joint.
    const std::string moved = "HIERARCHY\nROOT Pelvis\n{\n  OFFSET 0 0 0\n"
                              "  CHANNELS 3 Xposition Yposition Zposition\n"
                              "  JOINT Arm\n  {\n    OFFSET 0 10 0\n"
                              "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                              "    End Site\n    {\n      OFFSET 0 10 0\n    }\n  }\n}\n"
                              "MOTION\nFrames: 3\nFrame Time: 0.1\n"
                              "0 0 0 0 0 0\n10 0 0 30 0 0\n20 0 0 60 0 0\n";
    const Result<Animation> r = load_animation(write("root3.BVH", moved));
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(code_of(r), DiagnosticCode::bad_animation);
    EXPECT_NE(r.diagnostics.front().message.find("ROOT joint Pelvis"), std::string::npos)
        << r.diagnostics.front().message;
    EXPECT_NE(r.diagnostics.front().message.find("6 channels"), std::string::npos);
    // Only the root counts: the arm (6 channels at its root, rotations below) still loads.
    EXPECT_TRUE(load_animation(write("arm6.bvh", arm_bvh(12))).ok);
}

TEST(MotionLoadAnimation, GltfRoundTripKeepsBonesWeightsAndMotion)
{
    const auto scene = strip_scene(true);
    // glTF keeps seconds: tick 20 at 10 ticks per second is 2 s.
    expect_strip_read_back(export_scene(*scene, "glb2", "strip.glb"), 2.0);
    expect_strip_read_back(export_scene(*scene, "gltf2", "strip.gltf"), 2.0);
}

// assimp 5.2's Collada exporter writes key times that are not the scene's seconds (the strip's
// 0, 1, 2 s come out as 0 10 20 in <float_array id="Upper_matrix-input-array">): the test reads
// the time written in the file back from the file itself.
TEST(MotionLoadAnimation, ColladaRoundTripKeepsBonesWeightsAndMotion)
{
    const auto scene = strip_scene(true);
    const std::string path = export_scene(*scene, "collada", "strip.dae");
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string dae = text.str();
    const size_t array = dae.find("Upper_matrix-input-array");
    ASSERT_NE(array, std::string::npos);
    const size_t open = dae.find('>', array) + 1, close = dae.find('<', open);
    std::istringstream times(dae.substr(open, close - open));
    double t = 0.0, last = -1.0;
    while (times >> t)
        last = t;
    expect_strip_read_back(path, last);
}

// assimp 5.2's FBX exporter writes key times in ticks where FBX means seconds, and a take of the
// right length, to which the reader clips the keys (one frame is left): at one tick per second
// both agree. It does not read back its own binary FBX ("block offset is out of range"): ASCII.
TEST(MotionLoadAnimation, FbxRoundTripKeepsBonesWeightsAndMotion)
{
    const auto scene = strip_scene(true, 1.0);
    expect_strip_read_back(export_scene(*scene, "fbxa", "strip.fbx"), 2.0);
}

TEST(MotionLoadAnimation, AnUnskinnedMeshFollowsTheBoneThatCarriesIt)
{
    // The strip without skin, hung below the lower bone (at x = 4 at rest): it moves rigidly
    // with it. At 2 s the lower bone sits at R(60°)(4, 0) turned by 20°, so the vertex written at
    // (8, 0.5) (world (12, 0.5) at rest) goes to R(60°)(4, 0) + R(20°)(8, 0.5).
    auto scene = strip_scene(true);
    aiMesh* mesh = scene->mMeshes[0];
    for (unsigned b = 0; b < mesh->mNumBones; ++b)
        delete mesh->mBones[b];
    delete[] mesh->mBones;
    mesh->mBones = nullptr;
    mesh->mNumBones = 0;
    aiNode* root = scene->mRootNode;
    aiNode* body = root->mChildren[0];
    aiNode* lower = root->mChildren[1]->mChildren[0];
    root->mChildren[0] = root->mChildren[1];
    root->mNumChildren = 1;
    lower->mNumChildren = 1;
    lower->mChildren = new aiNode* [1] { body };
    body->mParent = lower;
    const Result<Animation> r = load_animation(export_scene(*scene, "glb2", "carried.glb"));
    ASSERT_TRUE(r.ok) << r.diagnostics[0].message;
    const Animation& a = r.value;
    ASSERT_EQ(a.mesh.vertices.size(), 10u);
    const int low = bone_named(a, "Lower");
    ASSERT_GE(low, 0);
    for (const auto& weights : a.skin) {
        ASSERT_EQ(weights.size(), 1u);
        EXPECT_EQ(weights[0].first, low);
    }
    const Vec3 expected = Vec3(4 * std::cos(60 * deg), 4 * std::sin(60 * deg), 0) +
                          Vec3(8 * std::cos(20 * deg) - 0.5 * std::sin(20 * deg),
                               8 * std::sin(20 * deg) + 0.5 * std::cos(20 * deg), 0);
    ASSERT_EQ(a.frames(), 3);
    double nearest = 1e9;
    for (const Vec3& p : posed_mesh(a, 2).vertices)
        nearest = std::min(nearest, (p - expected).norm());
    EXPECT_LT(nearest, 1e-5);
    // At the first frame the mesh is where the file puts it: (8, 0.5) + (4, 0).
    nearest = 1e9;
    for (const Vec3& p : posed_mesh(a, 0).vertices)
        nearest = std::min(nearest, (p - Vec3(12, 0.5, 0)).norm());
    EXPECT_LT(nearest, 1e-5);
}

TEST(MotionLoadAnimation, AStillSceneHasNoAnimation)
{
    const auto scene = strip_scene(false);
    EXPECT_EQ(code_of(load_animation(export_scene(*scene, "glb2", "still.glb"))),
              DiagnosticCode::no_animation);
}
