#include <algorithm>
#include <cmath>
#include <sstream>

#include "popup/motion/animation.hpp"

namespace popup {

namespace {

bool finite(const Eigen::Isometry3d& t)
{
    return t.matrix().allFinite();
}

/// Largest deviation of a transform's linear part from a rotation (R^T R = I, det R = 1).
double rotation_defect(const Eigen::Isometry3d& t)
{
    const Mat3 r = t.linear();
    return std::max((r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff(),
                    std::abs(r.determinant() - 1.0));
}

/// The bones on the cycle reached from `start` by following parents, or empty when it ends at a
/// root. Parents are in range here.
std::vector<int> cycle_from(const std::vector<Bone>& bones, int start)
{
    std::vector<int> seen_at(bones.size(), -1);
    std::vector<int> path;
    for (int b = start; b >= 0; b = bones[b].parent) {
        if (seen_at[b] >= 0) { // the cycle is the path from b's first visit on
            path.erase(path.begin(), path.begin() + seen_at[b]);
            return path;
        }
        seen_at[b] = int(path.size());
        path.push_back(b);
    }
    return {};
}

// Fails `result`, naming the animation, the reason and what it is about; false, so that a check
// can return it.
struct Refusal {
    Result<Animation>& result;
    const std::string& source;
    bool operator()(DiagnosticCode code, const std::string& why, const std::string& about) const
    {
        result.fail(code, "animation " + source + ": " + why, about_parameter(about));
        return false;
    }
};

// Bones: parents in range, no cycle, parents before their children.
bool check_skeleton(const Animation& animation, const Refusal& refuse)
{
    const std::string& source = animation.source;
    const int n = int(animation.bones.size());
    if (n == 0)
        return refuse(DiagnosticCode::bad_animation, "it has no bones", source);
    for (int b = 0; b < n; ++b) {
        const Bone& bone = animation.bones[b];
        if (bone.parent < -1 || bone.parent >= n || bone.parent == b)
            return refuse(DiagnosticCode::bad_animation,
                          "bone " + bone.name + " has parent index " + std::to_string(bone.parent) +
                              ", must be -1 (a root) or another bone's index in 0.." +
                              std::to_string(n - 1),
                          bone.name);
    }
    for (int b = 0; b < n; ++b) {
        const std::vector<int> cycle = cycle_from(animation.bones, b);
        if (cycle.empty())
            continue;
        std::ostringstream names;
        for (size_t k = 0; k < cycle.size(); ++k)
            names << (k ? " -> " : "") << animation.bones[cycle[k]].name;
        names << " -> " << animation.bones[cycle[0]].name;
        return refuse(DiagnosticCode::skeleton_cycle,
                      "the skeleton has a cycle: " + names.str() +
                          " (each bone's parent after the arrow); a skeleton must be a tree",
                      animation.bones[cycle[0]].name);
    }
    for (int b = 0; b < n; ++b)
        if (animation.bones[b].parent > b)
            return refuse(DiagnosticCode::bad_animation,
                          "bone " + animation.bones[b].name + " (index " + std::to_string(b) +
                              ") comes before its parent " +
                              animation.bones[animation.bones[b].parent].name + " (index " +
                              std::to_string(animation.bones[b].parent) +
                              "); parents must come first",
                          animation.bones[b].name);
    return true;
}

// Frames: at least two, at finite ascending times, each a rigid transform per bone.
bool check_frames(const Animation& animation, const Refusal& refuse)
{
    const std::string& source = animation.source;
    const int n = int(animation.bones.size());
    const int frames = animation.frames();
    if (frames == 0)
        return refuse(DiagnosticCode::no_animation, "it has no frames (no animation)", source);
    if (frames == 1)
        return refuse(DiagnosticCode::single_frame,
                      "it has a single frame: there is no motion to follow (at least 2 needed)",
                      source);
    for (int f = 0; f < frames; ++f) {
        const double t = animation.frame_times_s[f];
        if (!std::isfinite(t))
            return refuse(DiagnosticCode::non_finite_animation,
                          "frame " + std::to_string(f) + " time = " + std::to_string(t) +
                              " s, must be finite",
                          "frame_times_s");
        if (f > 0 && !(t > animation.frame_times_s[f - 1]))
            return refuse(DiagnosticCode::bad_animation,
                          "frame " + std::to_string(f) + " time " + std::to_string(t) +
                              " s is not after frame " + std::to_string(f - 1) + "'s " +
                              std::to_string(animation.frame_times_s[f - 1]) +
                              " s; times must be strictly ascending",
                          "frame_times_s");
    }
    if (int(animation.local.size()) != frames)
        return refuse(DiagnosticCode::bad_animation,
                      "it has " + std::to_string(animation.local.size()) +
                          " frames of transforms for " + std::to_string(frames) + " frame times",
                      "local");
    for (int f = 0; f < frames; ++f) {
        if (int(animation.local[f].size()) != n)
            return refuse(DiagnosticCode::bad_animation,
                          "frame " + std::to_string(f) + " has " +
                              std::to_string(animation.local[f].size()) + " transforms for " +
                              std::to_string(n) + " bones",
                          "local");
        for (int b = 0; b < n; ++b) {
            const Eigen::Isometry3d& t = animation.local[f][b];
            if (!finite(t))
                return refuse(DiagnosticCode::non_finite_animation,
                              "bone " + animation.bones[b].name + " at frame " + std::to_string(f) +
                                  " has a NaN or infinite transform",
                              animation.bones[b].name);
            if (rotation_defect(t) > 1e-6)
                return refuse(DiagnosticCode::bad_animation,
                              "bone " + animation.bones[b].name + " at frame " + std::to_string(f) +
                                  " has a transform that is not a rotation and a translation "
                                  "(deviation " +
                                  std::to_string(rotation_defect(t)) + ", at most 1e-6)",
                              animation.bones[b].name);
        }
    }
    return true;
}

// The joints' extent over every frame, as check_model bounds a model's: a root jumping to
// 1e30 would shrink the character on the card to a point (parents precede their children).
bool check_extent(const Animation& animation, const Refusal& refuse)
{
    const int n = int(animation.bones.size());
    const int frames = animation.frames();
    Eigen::AlignedBox3d joints;
    for (int f = 0; f < frames; ++f) {
        std::vector<Eigen::Isometry3d> global(n);
        for (int b = 0; b < n; ++b) {
            const int p = animation.bones[b].parent;
            global[b] = p < 0 ? animation.local[f][b] : global[p] * animation.local[f][b];
            joints.extend(global[b].translation());
        }
    }
    const double extent = joints.diagonal().norm();
    if (!(extent <= 1e6) || (extent > 0.0 && extent < 1e-6)) {
        std::ostringstream why;
        why << "its joints span a bounding-box diagonal of " << extent
            << " units over its frames, must be in 1e-6..1e6";
        return refuse(DiagnosticCode::bad_animation, why.str(), "local");
    }
    return true;
}

// Bind transforms: one per bone (identity when none are given), finite.
bool check_bind(Animation& animation, const Refusal& refuse)
{
    const int n = int(animation.bones.size());
    if (animation.bind_inverse.empty())
        animation.bind_inverse.assign(n, Eigen::Isometry3d::Identity());
    if (int(animation.bind_inverse.size()) != n)
        return refuse(DiagnosticCode::bad_animation,
                      "it has " + std::to_string(animation.bind_inverse.size()) +
                          " bind transforms for " + std::to_string(n) + " bones",
                      "bind_inverse");
    for (int b = 0; b < n; ++b)
        if (!finite(animation.bind_inverse[b]))
            return refuse(DiagnosticCode::non_finite_animation,
                          "bone " + animation.bones[b].name +
                              " has a NaN or infinite bind transform",
                          animation.bones[b].name);
    return true;
}

// The skin: a valid mesh with weights to existing bones summing to 1 per vertex, or neither.
bool check_skin(Animation& animation, const Refusal& refuse)
{
    const std::string& source = animation.source;
    const int n = int(animation.bones.size());
    if (animation.mesh.vertices.empty()) {
        if (!animation.skin.empty())
            return refuse(DiagnosticCode::bad_animation,
                          "it has skin weights for " + std::to_string(animation.skin.size()) +
                              " vertices but no mesh",
                          "skin");
    } else {
        if (animation.mesh.source.empty())
            animation.mesh.source = source;
        Result<ModelMesh> mesh = check_model(animation.mesh);
        if (!mesh.ok) {
            refuse.result.fail_with(mesh.diagnostics);
            return false;
        }
        const size_t vertices = animation.mesh.vertices.size();
        if (animation.skin.size() != vertices)
            return refuse(DiagnosticCode::bad_animation,
                          "it has skin weights for " + std::to_string(animation.skin.size()) +
                              " vertices, the mesh has " + std::to_string(vertices),
                          "skin");
        for (size_t v = 0; v < vertices; ++v) {
            const std::string vertex = "vertex " + std::to_string(v);
            double sum = 0.0;
            if (animation.skin[v].empty())
                return refuse(DiagnosticCode::bad_animation, vertex + " has no skin weights",
                              "skin");
            for (const auto& [bone, weight] : animation.skin[v]) {
                if (bone < 0 || bone >= n)
                    return refuse(DiagnosticCode::bad_animation,
                                  vertex + " is weighted to bone index " + std::to_string(bone) +
                                      ", must be in 0.." + std::to_string(n - 1),
                                  "skin");
                if (!std::isfinite(weight))
                    return refuse(DiagnosticCode::non_finite_animation,
                                  vertex + " has a NaN or infinite weight for bone " +
                                      animation.bones[bone].name,
                                  "skin");
                if (weight < 0.0)
                    return refuse(DiagnosticCode::bad_animation,
                                  vertex + " has weight " + std::to_string(weight) + " for bone " +
                                      animation.bones[bone].name + ", must be >= 0",
                                  "skin");
                sum += weight;
            }
            if (std::abs(sum - 1.0) > 1e-6)
                return refuse(DiagnosticCode::bad_animation,
                              vertex + "'s weights sum to " + std::to_string(sum) +
                                  ", must sum to 1 (within 1e-6)",
                              "skin");
        }
    }
    return true;
}

} // namespace

Result<Animation> check_animation(Animation animation)
{
    Result<Animation> result;
    const Refusal refuse{result, animation.source};
    if (!check_skeleton(animation, refuse) || !check_frames(animation, refuse) ||
        !check_extent(animation, refuse) || !check_bind(animation, refuse) ||
        !check_skin(animation, refuse))
        return result;
    result.value = std::move(animation);
    return result;
}

} // namespace popup
