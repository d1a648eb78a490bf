#include "keyed_clip.hpp"

#include <algorithm>

#include "on_cores.hpp"

namespace popup::motion {

namespace {

using Affine = Eigen::Matrix4d;

/// Below this many bone transforms (frames × bones) the frames are made on one thread.
constexpr std::size_t transforms_for_threads = 20000;
/// Frames made as one task (read_frames).
constexpr std::size_t frames_per_block = 64;

/// A channel's value at a time in ticks: neighbouring keys lerped (slerped for rotations), the
/// end keys held outside them.
template <class Key, class Blend>
auto sample(const std::vector<Key>& key_list, double time, Blend blend)
{
    const Key* keys = key_list.data();
    const std::size_t count = key_list.size();
    if (count == 1 || time <= keys[0].mTime)
        return keys[0].mValue;
    if (time >= keys[count - 1].mTime)
        return keys[count - 1].mValue;
    const Key* next = std::upper_bound(keys, keys + count, time,
                                       [](double t, const Key& k) { return t < k.mTime; });
    const Key* prev = next - 1;
    const double span = next->mTime - prev->mTime;
    const double u = span > 0 ? (time - prev->mTime) / span : 0.0;
    return blend(prev->mValue, next->mValue, float(u));
}

/// A bone's rest transform as assimp decomposes it (in floats), for the channels it lacks.
struct RestParts {
    aiVector3D scaling, position;
    aiQuaternion rotation;
};

RestParts rest_parts(const Affine& rest)
{
    RestParts out;
    aiMatrix4x4 rest_ai;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            rest_ai[i][j] = float(rest(i, j));
    rest_ai.Decompose(out.scaling, out.rotation, out.position);
    return out;
}

Affine channel_transform(const BoneKeys& keys, double time, const RestParts& rest)
{
    auto lerp = [](const aiVector3D& a, const aiVector3D& b, float u) { return a + (b - a) * u; };
    auto slerp = [](const aiQuaternion& a, const aiQuaternion& b, float u) {
        aiQuaternion out;
        aiQuaternion::Interpolate(out, a, b, u);
        return out.Normalize();
    };
    const aiVector3D position =
        keys.positions.empty() ? rest.position : sample(keys.positions, time, lerp);
    const aiQuaternion rotation =
        keys.rotations.empty() ? rest.rotation : sample(keys.rotations, time, slerp);
    const aiVector3D scaling =
        keys.scalings.empty() ? rest.scaling : sample(keys.scalings, time, lerp);
    // Rotations in double: assimp's float matrices would cost 1e-7 per frame.
    const Eigen::Quaterniond q(rotation.w, rotation.x, rotation.y, rotation.z);
    Affine m = Affine::Identity();
    m.topLeftCorner<3, 3>() =
        q.normalized().toRotationMatrix() * Vec3(scaling.x, scaling.y, scaling.z).asDiagonal();
    m.topRightCorner<3, 1>() = Vec3(position.x, position.y, position.z);
    return m;
}

/// Globals at a tick, the rest poses decomposed once for all frames.
class ClipSampler {
public:
    ClipSampler(const KeyedClip& clip, const std::vector<Bone>& bones) : clip(clip), bones(bones)
    {
        rest.reserve(clip.bones.size());
        for (const BoneKeys& k : clip.bones)
            rest.push_back(k.animated ? rest_parts(k.rest) : RestParts());
    }

    void globals(double tick, std::vector<Affine>& global) const
    {
        for (std::size_t b = 0; b < clip.bones.size(); ++b) {
            const BoneKeys& keys = clip.bones[b];
            const Affine local = keys.animated ? channel_transform(keys, tick, rest[b]) : keys.rest;
            const int p = bones[b].parent;
            global[b] = p >= 0 ? Affine(global[p] * local) : local;
        }
    }

private:
    const KeyedClip& clip;
    const std::vector<Bone>& bones;
    std::vector<RestParts> rest;
};

} // namespace

Eigen::Isometry3d rigid_part(const Affine& a)
{
    const Eigen::JacobiSVD<Mat3> svd(a.topLeftCorner<3, 3>(),
                                     Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 r = svd.matrixU() * svd.matrixV().transpose();
    if (r.determinant() < 0) { // a mirror: keep a rotation, flip the weakest axis
        Mat3 u = svd.matrixU();
        u.col(2) *= -1.0;
        r = u * svd.matrixV().transpose();
    }
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = r;
    out.translation() = a.topRightCorner<3, 1>();
    return out;
}

BoneKeys bone_keys(const aiNodeAnim* channel, const Affine& rest)
{
    BoneKeys keys;
    keys.rest = rest;
    if (!channel)
        return keys;
    keys.animated = true;
    keys.positions.assign(channel->mPositionKeys,
                          channel->mPositionKeys + channel->mNumPositionKeys);
    keys.rotations.assign(channel->mRotationKeys,
                          channel->mRotationKeys + channel->mNumRotationKeys);
    keys.scalings.assign(channel->mScalingKeys, channel->mScalingKeys + channel->mNumScalingKeys);
    return keys;
}

void globals_at(const KeyedClip& clip, const std::vector<Bone>& bones, double tick,
                std::vector<Affine>& global)
{
    ClipSampler(clip, bones).globals(tick, global);
}

void read_frames(const KeyedClip& clip, Animation& animation)
{
    const std::size_t n = clip.bones.size(), frames = clip.frame_ticks.size();
    const ClipSampler sampler(clip, animation.bones);
    animation.local.assign(frames, {});
    // Each frame is made from its keys alone, so blocks of frames are shared out among the
    // cores (4,500 frames of 83 bones: 0.37 s on one).
    auto make_block = [&](std::size_t block) {
        std::vector<Affine> global(n);
        std::vector<Eigen::Isometry3d> rigid(n);
        const std::size_t to = std::min(frames, (block + 1) * frames_per_block);
        for (std::size_t f = block * frames_per_block; f < to; ++f) {
            sampler.globals(clip.frame_ticks[f], global);
            for (std::size_t b = 0; b < n; ++b)
                rigid[b] = rigid_part(global[b]);
            std::vector<Eigen::Isometry3d>& local = animation.local[f];
            local.resize(n);
            for (std::size_t b = 0; b < n; ++b) {
                const int p = animation.bones[b].parent;
                local[b] = p >= 0 ? rigid[p].inverse() * rigid[b] : rigid[b];
                local[b].linear() =
                    Eigen::Quaterniond(local[b].linear()).normalized().toRotationMatrix();
            }
        }
    };
    run_on_cores((frames + frames_per_block - 1) / frames_per_block, make_block,
                 frames * n >= transforms_for_threads);
}

void put_clip(ByteWriter& w, const KeyedClip& clip)
{
    w.put_all(clip.frame_ticks);
    for (const BoneKeys& k : clip.bones) {
        w.bytes.append(reinterpret_cast<const char*>(k.rest.data()), 16 * sizeof(double));
        w.put(std::uint8_t(k.animated));
        w.put_all(k.positions);
        w.put_all(k.rotations);
        w.put_all(k.scalings);
    }
}

void get_clip(ByteReader& r, std::size_t bone_count, KeyedClip& clip)
{
    r.get_all(clip.frame_ticks);
    clip.bones.resize(bone_count);
    for (BoneKeys& k : clip.bones) {
        for (int i = 0; i < 16 && r.fine; ++i)
            k.rest.data()[i] = r.get<double>();
        k.animated = r.get<std::uint8_t>() != 0;
        r.get_all(k.positions);
        r.get_all(k.rotations);
        r.get_all(k.scalings);
        if (!r.fine)
            return;
    }
}

} // namespace popup::motion
