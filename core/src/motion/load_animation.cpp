// load_animation: an animated character through assimp, read in a child process as load_model
// reads a model (core/src/input/child_process.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "../input/child_process.hpp"
#include "../input/model_mesh_bytes.hpp"
#include "bvh_root_channels.hpp"
#include "keyed_clip.hpp"
#include "popup/motion/animation.hpp"

namespace popup {

namespace {

namespace fs = std::filesystem;

using motion::KeyedClip;
using motion::rigid_part;

using Affine = Eigen::Matrix4d;

Affine affine(const aiMatrix4x4& m)
{
    Affine a;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            a(r, c) = m[r][c];
    return a;
}

double uniform_scale(const Affine& a)
{
    return std::cbrt(std::abs(a.topLeftCorner<3, 3>().determinant()));
}

/// What the child sends back: a diagnostic code name and why ("" when read), then the animation.
struct Read {
    std::string code = "unreadable_model";
    std::string why;
    Animation animation;
    KeyedClip clip; ///< the frames' keys: the caller makes animation.local from them
};

/// assimp's drawing of a skeleton (SkeletonMeshBuilder, for files without a mesh), not a mesh of
/// the character.
bool drawn_skeleton(const aiScene* scene, const aiMesh* mesh)
{
    if (mesh->mMaterialIndex >= scene->mNumMaterials)
        return false;
    aiString name;
    return scene->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
           std::string(name.C_Str()) == "SkeletonMaterial";
}

void collect(const aiNode* node, int parent_node, std::vector<const aiNode*>& nodes,
             std::vector<int>& parents)
{
    const int me = int(nodes.size());
    nodes.push_back(node);
    parents.push_back(parent_node);
    for (unsigned c = 0; c < node->mNumChildren; ++c)
        collect(node->mChildren[c], me, nodes, parents);
}

/// The scene's node tree (parents before children) and which nodes are the animation's bones.
struct SceneBones {
    std::vector<const aiNode*> nodes;
    std::vector<int> node_parent;
    std::map<std::string, int> node_named;     ///< the first node of each name
    std::vector<const aiNodeAnim*> channel_of; ///< per node, its keyframe channel or none
    std::vector<int> bone_of;                  ///< per node, its bone or -1
    std::vector<int> node_of_bone;             ///< per bone, its node
};

/// The node tree and its bones (written to animation.bones, parents first).
SceneBones scene_bones(const aiScene* scene, const aiAnimation* clip, Animation& animation)
{
    SceneBones s;
    std::vector<const aiNode*>& nodes = s.nodes;
    std::vector<int>& node_parent = s.node_parent;
    collect(scene->mRootNode, -1, nodes, node_parent);
    std::map<std::string, int>& node_named = s.node_named;
    for (size_t i = 0; i < nodes.size(); ++i)
        node_named.emplace(nodes[i]->mName.C_Str(), int(i)); // the first of a repeated name

    // Bones: animated nodes, skin bones, their ancestors, and the childless nodes below an
    // animated one (BVH end sites).
    std::vector<const aiNodeAnim*>& channel_of = s.channel_of;
    channel_of.assign(nodes.size(), nullptr);
    std::vector<char> is_bone(nodes.size(), 0), animated_below(nodes.size(), 0);
    for (unsigned c = 0; c < clip->mNumChannels; ++c) {
        auto it = node_named.find(clip->mChannels[c]->mNodeName.C_Str());
        if (it != node_named.end()) {
            channel_of[it->second] = clip->mChannels[c];
            is_bone[it->second] = 1;
        }
    }
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b) {
            auto it = node_named.find(scene->mMeshes[m]->mBones[b]->mName.C_Str());
            if (it != node_named.end())
                is_bone[it->second] = 1;
        }
    for (size_t i = 0; i < nodes.size(); ++i) { // parents come first in `nodes`
        const int p = node_parent[i];
        animated_below[i] = (p >= 0 && (animated_below[p] || channel_of[p])) ? 1 : 0;
        if (animated_below[i] && nodes[i]->mNumChildren == 0 && nodes[i]->mNumMeshes == 0)
            is_bone[i] = 1;
    }
    for (int i = int(nodes.size()) - 1; i >= 0; --i)
        if (is_bone[i] && node_parent[i] >= 0)
            is_bone[node_parent[i]] = 1;
    std::vector<int>& bone_of = s.bone_of;
    bone_of.assign(nodes.size(), -1);
    for (size_t i = 0; i < nodes.size(); ++i)
        if (is_bone[i]) {
            bone_of[i] = int(animation.bones.size());
            const int p = node_parent[i];
            animation.bones.push_back({nodes[i]->mName.C_Str(), p >= 0 ? bone_of[p] : -1});
        }
    std::vector<int>& node_of_bone = s.node_of_bone;
    for (size_t i = 0; i < nodes.size(); ++i)
        if (is_bone[i])
            node_of_bone.push_back(int(i));

    return s;
}

/// The frames' times in ticks: every key time of every channel, nearly equal ones merged.
std::vector<double> frame_ticks_of(const aiAnimation* clip)
{
    // Frames: every key time of every channel.
    std::set<double> ticks;
    for (unsigned c = 0; c < clip->mNumChannels; ++c) {
        const aiNodeAnim* ch = clip->mChannels[c];
        for (unsigned k = 0; k < ch->mNumPositionKeys; ++k)
            ticks.insert(ch->mPositionKeys[k].mTime);
        for (unsigned k = 0; k < ch->mNumRotationKeys; ++k)
            ticks.insert(ch->mRotationKeys[k].mTime);
        for (unsigned k = 0; k < ch->mNumScalingKeys; ++k)
            ticks.insert(ch->mScalingKeys[k].mTime);
    }
    std::vector<double> frame_ticks;
    for (double t : ticks)
        if (frame_ticks.empty() || t - frame_ticks.back() > 1e-6 * std::max(1.0, std::abs(t)))
            frame_ticks.push_back(t);

    return frame_ticks;
}

/// The bones' keys (the frames' transforms are made from them by the caller, read_frames).
KeyedClip keyed_clip(const SceneBones& s, std::vector<double> frame_ticks)
{
    KeyedClip clip;
    clip.frame_ticks = std::move(frame_ticks);
    for (int node : s.node_of_bone)
        clip.bones.push_back(
            motion::bone_keys(s.channel_of[node], affine(s.nodes[node]->mTransformation)));
    return clip;
}

/// The bones' global transforms at the first frame (affine: the skin's scale is read from them).
std::vector<Affine> globals_at_first(const KeyedClip& clip, const std::vector<Bone>& bones)
{
    std::vector<Affine> global(bones.size());
    if (!clip.frame_ticks.empty())
        motion::globals_at(clip, bones, clip.frame_ticks.front(), global);
    return global;
}

/// The skinned mesh into animation.mesh, .skin and .bind_inverse.
void read_skin(const aiScene* scene, const SceneBones& s,
               const std::vector<Affine>& global_at_first, const std::string& path,
               Animation& animation)
{
    const std::vector<const aiNode*>& nodes = s.nodes;
    const std::vector<int>& node_parent = s.node_parent;
    const std::map<std::string, int>& node_named = s.node_named;
    const std::vector<int>& bone_of = s.bone_of;
    const int n = int(s.node_of_bone.size());
    // The skinned mesh: vertices scaled to the bones' units, offsets made rigid.
    animation.bind_inverse.assign(n, Eigen::Isometry3d::Identity());
    std::vector<char> bind_set(n, 0);
    std::map<const aiMesh*, int> node_of_mesh;
    for (size_t i = 0; i < nodes.size(); ++i)
        for (unsigned k = 0; k < nodes[i]->mNumMeshes; ++k)
            if (nodes[i]->mMeshes[k] < scene->mNumMeshes)
                node_of_mesh.emplace(scene->mMeshes[nodes[i]->mMeshes[k]], int(i));
    /// The nearest bone at or above a node, and the node's transform below that bone.
    auto carrier = [&](int node, Affine& below) {
        below = Affine::Identity();
        for (int i = node; i >= 0; i = node_parent[i]) {
            if (bone_of[i] >= 0)
                return bone_of[i];
            below = affine(nodes[i]->mTransformation) * below;
        }
        return -1;
    };
    ModelMesh& mesh = animation.mesh;
    mesh.source = path;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* part = scene->mMeshes[m];
        if (!(part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || drawn_skeleton(scene, part))
            continue;
        Affine below_bone = Affine::Identity();
        const int host_bone =
            node_of_mesh.count(part) ? carrier(node_of_mesh[part], below_bone) : -1;
        if (part->mNumBones == 0 && host_bone < 0)
            continue; // neither skinned nor carried by a bone: not part of the character
        std::vector<std::vector<std::pair<int, double>>> weights(part->mNumVertices);
        double scale = 1.0; // mesh units to the bones' units
        bool scale_known = false;
        for (unsigned k = 0; k < part->mNumBones; ++k) {
            const aiBone* bone = part->mBones[k];
            auto it = node_named.find(bone->mName.C_Str());
            if (it == node_named.end() || bone_of[it->second] < 0)
                continue;
            const int b = bone_of[it->second];
            // world = G_b · offset · v = rigid(G_b) · (σ_b · offset) · v, σ_b G_b's scale.
            const Affine scaled = uniform_scale(global_at_first[b]) * affine(bone->mOffsetMatrix);
            if (!scale_known) {
                scale = uniform_scale(scaled);
                scale_known = scale > 0;
            }
            if (!bind_set[b]) {
                Affine unit = scaled;
                unit.topLeftCorner<3, 3>() /= scale;
                animation.bind_inverse[b] = rigid_part(unit);
                bind_set[b] = 1;
            }
            for (unsigned w = 0; w < bone->mNumWeights; ++w) {
                const aiVertexWeight& vw = bone->mWeights[w];
                if (vw.mVertexId < part->mNumVertices && vw.mWeight > 0)
                    weights[vw.mVertexId].emplace_back(b, vw.mWeight);
            }
        }
        // An unskinned part, or unweighted vertices, follow the bone that carries the mesh:
        // their place at the first frame, expressed in that bone's bind space.
        Affine carried = Affine::Identity();
        if (host_bone >= 0) {
            if (!bind_set[host_bone]) {
                animation.bind_inverse[host_bone] =
                    rigid_part(global_at_first[host_bone]).inverse();
                bind_set[host_bone] = 1;
            }
            // v' with rigid(G(0)) · bind_inverse · v' = G(0) · below · v, its first-frame place.
            carried = animation.bind_inverse[host_bone].inverse().matrix() *
                      rigid_part(global_at_first[host_bone]).inverse().matrix() *
                      global_at_first[host_bone] * below_bone;
        }
        const int offset = int(mesh.vertices.size());
        for (unsigned v = 0; v < part->mNumVertices; ++v) {
            const Vec3 p(part->mVertices[v].x, part->mVertices[v].y, part->mVertices[v].z);
            auto& w = weights[v];
            if (w.empty() && host_bone >= 0) {
                mesh.vertices.push_back((carried * p.homogeneous()).head<3>());
                w.emplace_back(host_bone, 1.0);
            } else {
                mesh.vertices.push_back(scale * p);
            }
            double sum = 0.0;
            for (const auto& bw : w)
                sum += bw.second;
            for (auto& bw : w)
                bw.second = sum > 0 ? bw.second / sum : 1.0 / double(w.size());
            if (w.empty())
                w.emplace_back(0, 1.0); // no bone and no host: the root's
            animation.skin.push_back(std::move(w));
        }
        for (unsigned f = 0; f < part->mNumFaces; ++f) {
            const aiFace& face = part->mFaces[f];
            if (face.mNumIndices == 3)
                mesh.triangles.push_back({offset + int(face.mIndices[0]),
                                          offset + int(face.mIndices[1]),
                                          offset + int(face.mIndices[2])});
        }
    }
}

void read_with_assimp(const std::string& path, Read& out)
{
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // BVH has no mesh: assimp would make one that draws the skeleton.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    // FBX: one node per bone, not helper nodes for each pivot ("$AssimpFbx$_Rotation").
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (!scene) {
        out.why = std::string("assimp could not read it: ") + importer.GetErrorString();
        return;
    }
    if (!scene->mRootNode) {
        out.why = "assimp read no node hierarchy";
        return;
    }
    if (scene->mNumAnimations == 0 || !scene->mAnimations[0] ||
        scene->mAnimations[0]->mNumChannels == 0) {
        out.code = "no_animation";
        out.why = "it has no animation (no keyframe channels)";
        return;
    }
    const aiAnimation* clip = scene->mAnimations[0];
    const double ticks_per_second = clip->mTicksPerSecond > 0 ? clip->mTicksPerSecond : 25.0;

    Animation& animation = out.animation;
    animation.source = path;
    const SceneBones bones = scene_bones(scene, clip, animation);
    out.clip = keyed_clip(bones, frame_ticks_of(clip));
    for (double t : out.clip.frame_ticks)
        animation.frame_times_s.push_back(t / ticks_per_second);
    read_skin(scene, bones, globals_at_first(out.clip, animation.bones), path, animation);
    out.code.clear();
}

// Across the pipe: code, why, then the animation's fields in order.
std::string encode(const Read& read)
{
    ByteWriter w;
    w.put_text(read.code);
    w.put_text(read.why);
    const Animation& a = read.animation;
    w.put(std::uint64_t(a.bones.size()));
    for (const Bone& b : a.bones) {
        w.put_text(b.name);
        w.put(b.parent);
    }
    w.put_all(a.frame_times_s);
    motion::put_clip(w, read.clip);
    put_mesh(w, a.mesh);
    std::vector<double> numbers;
    for (const Eigen::Isometry3d& t : a.bind_inverse)
        numbers.insert(numbers.end(), t.matrix().data(), t.matrix().data() + 16);
    w.put_all(numbers);
    std::vector<int> counts, bones;
    std::vector<double> weights;
    for (const auto& vertex : a.skin) {
        counts.push_back(int(vertex.size()));
        for (const auto& [b, weight] : vertex) {
            bones.push_back(b);
            weights.push_back(weight);
        }
    }
    w.put_all(counts);
    w.put_all(bones);
    w.put_all(weights);
    return w.bytes;
}

bool decode(const std::string& bytes, Read& read)
{
    ByteReader r{bytes};
    read.code = r.get_text();
    read.why = r.get_text();
    Animation& a = read.animation;
    const auto n = r.get<std::uint64_t>();
    if (!r.fine || n > bytes.size())
        return false;
    for (std::uint64_t b = 0; b < n && r.fine; ++b) {
        Bone bone;
        bone.name = r.get_text();
        bone.parent = r.get<int>();
        a.bones.push_back(bone);
    }
    r.get_all(a.frame_times_s);
    motion::get_clip(r, n, read.clip);
    if (!r.fine || read.clip.frame_ticks.size() != a.frame_times_s.size())
        return false;
    std::vector<double> numbers;
    auto isometry = [&](size_t at) {
        Eigen::Isometry3d t;
        t.matrix() = Eigen::Map<const Eigen::Matrix4d>(numbers.data() + at);
        return t;
    };
    get_mesh(r, a.mesh);
    r.get_all(numbers);
    if (!r.fine || numbers.size() != n * 16)
        return false;
    for (size_t b = 0; b < n; ++b)
        a.bind_inverse.push_back(isometry(16 * b));
    std::vector<int> counts, bones;
    std::vector<double> weights;
    r.get_all(counts);
    r.get_all(bones);
    r.get_all(weights);
    if (!r.whole() || bones.size() != weights.size())
        return false;
    size_t at = 0;
    for (int count : counts) {
        if (count < 0 || at + size_t(count) > bones.size())
            return false;
        std::vector<std::pair<int, double>> vertex;
        for (int k = 0; k < count; ++k, ++at)
            vertex.emplace_back(bones[at], weights[at]);
        a.skin.push_back(std::move(vertex));
    }
    return at == bones.size();
}

} // namespace

Result<Animation> load_animation(const std::string& path, const LoadAnimationOptions& options)
{
    Result<Animation> result;
    auto refuse = [&](DiagnosticCode code, const std::string& why) {
        result.fail(code, "animation file " + path + ": " + why, about_parameter(path));
        return result;
    };
    std::error_code error;
    if (path.empty())
        return refuse(DiagnosticCode::unreadable_model, "no path given");
    if (!fs::exists(path, error))
        return refuse(DiagnosticCode::unreadable_model, "no such file");
    if (!fs::is_regular_file(path, error))
        return refuse(DiagnosticCode::unreadable_model, "not a regular file");
    if (!(options.timeout_s > 0.0))
        return refuse(DiagnosticCode::unreadable_model,
                      "timeout_s = " + std::to_string(options.timeout_s) + ", must be > 0");
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".bvh") {
        const std::string root = motion::bvh_position_only_root(path);
        if (!root.empty())
            return refuse(DiagnosticCode::bad_animation,
                          "its ROOT joint " + root +
                              " has only the 3 position channels; assimp 5.2 reads such a root "
                              "without its motion: export the root with 6 channels (Xposition "
                              "Yposition Zposition Zrotation Xrotation Yrotation)");
    }
    std::string bytes;
    const std::string failed = run_in_child(
        [&] {
            Read read;
            try {
                read_with_assimp(path, read);
            } catch (const std::exception& e) {
                read = Read();
                read.why = std::string("assimp failed: ") + e.what();
            }
            return encode(read);
        },
        options.timeout_s, bytes);
    if (!failed.empty())
        return refuse(DiagnosticCode::unreadable_model, failed);
    Read read;
    if (!decode(bytes, read))
        return refuse(DiagnosticCode::unreadable_model,
                      "the reader process ended without a whole answer");
    if (!read.code.empty()) {
        const auto code = diagnostic_code_named(read.code);
        return refuse(code ? *code : DiagnosticCode::unreadable_model, read.why);
    }
    read.animation.source = path;
    motion::read_frames(read.clip, read.animation);
    read.clip = KeyedClip(); // its keys are not needed past here
    return check_animation(std::move(read.animation));
}

} // namespace popup
