// Forward kinematics over the frame range, projection on the card, adaptive sampling
// (thesis §6.2; docs/MATH.md, Motion targets).
#include "popup/motion/motion_targets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "popup/motion/adaptive_samples.hpp"

namespace popup {

namespace {

/// Rows: the card's x, y, z axes in the file's axes. z points at the viewer (against `view`), y
/// is `up` made perpendicular to it, x = y × z (right-handed).
Mat3 card_axes(const Vec3& view, const Vec3& up)
{
    const Vec3 z = -view.normalized();
    const Vec3 y = (up - up.dot(z) * z).normalized();
    Mat3 r;
    r.row(0) = y.cross(z);
    r.row(1) = y;
    r.row(2) = z;
    return r;
}

/// At most this many frames are skinned to find the character's extent (every k-th frame).
constexpr int skinned_frames_for_extent = 32;

// Fails `result` naming the view's option, why, and the option as the subject; false, so that a
// check can return it.
struct ViewRefusal {
    Result<MotionTargets>& result;
    bool operator()(const std::string& option, const std::string& why) const
    {
        result.fail(DiagnosticCode::bad_option, "motion view: " + option + " " + why,
                    about_parameter(option));
        return false;
    }
};

// The view's options (check_motion_view), then its frame range against the animation's frames.
bool check_view(const Animation& animation, const MotionView& view, const ViewRefusal& refuse)
{
    const int frames = animation.frames();
    if (frames < 2 || animation.local.size() != size_t(frames))
        return refuse("animation", "has " + std::to_string(frames) +
                                       " frames; check_animation it first (at least 2 needed)");
    const Diagnostics bad = check_motion_view(view);
    if (!bad.empty()) {
        refuse.result.fail_with(bad);
        return false;
    }
    const int first = view.first_frame;
    const int last = view.last_frame < 0 ? frames - 1 : view.last_frame;
    if (first > frames - 1)
        return refuse("first_frame", "= " + std::to_string(first) + ", must be in 0.." +
                                         std::to_string(frames - 2));
    if (last > frames - 1 || last <= first)
        return refuse("last_frame",
                      "= " + std::to_string(view.last_frame) + ", must be -1 (the last) or in " +
                          std::to_string(first + 1) + ".." + std::to_string(frames - 1) +
                          " (after first_frame " + std::to_string(first) + ")");
    return true;
}

/// The part of `moved` along the ground: across `up` (unit), what the walk travels.
Vec3 along_ground(const Vec3& up, const Vec3& moved)
{
    return moved - up * up.dot(moved);
}

/// Poses with the root's travel along the ground taken out (docs/MATH.md, "A walk stays on the
/// card"): at each frame the whole skeleton moves back by its first root's travel across `up`
/// since the last frame, so the last frame, whose posed mesh the card prints, is the file's own.
struct InPlace {
    const Animation& animation;
    bool on = false;
    int bone = 0;                ///< character_root
    Vec3 up = Vec3::UnitY();     ///< unit
    Vec3 at_last = Vec3::Zero(); ///< the first root at the last frame

    InPlace(const Animation& a, const Vec3& up_, int last, bool remove)
        : animation(a), on(remove), bone(character_root(a)), up(up_.normalized())
    {
        at_last = forward_kinematics(a, double(last))[bone].translation();
    }
    /// How far the character has travelled along the ground in the pose `global`.
    Vec3 travel(const std::vector<Eigen::Isometry3d>& global) const
    {
        return on ? along_ground(up, global[bone].translation() - at_last) : Vec3::Zero();
    }
    std::vector<Eigen::Isometry3d> pose(double frame) const
    {
        std::vector<Eigen::Isometry3d> global = forward_kinematics(animation, frame);
        const Vec3 back = travel(global);
        for (Eigen::Isometry3d& g : global)
            g.pretranslate(-back);
        return global;
    }
    ModelMesh mesh(double frame) const
    {
        ModelMesh posed = posed_mesh(animation, frame);
        const Vec3 back = travel(forward_kinematics(animation, frame));
        for (Vec3& v : posed.vertices)
            v -= back;
        return posed;
    }
};

} // namespace

Vec3 ground_travel(const Animation& animation, const Vec3& up, int last_frame, double frame)
{
    const int bone = character_root(animation);
    return along_ground(up.normalized(),
                        forward_kinematics(animation, frame)[bone].translation() -
                            forward_kinematics(animation, double(last_frame))[bone].translation());
}

Result<MotionTargets> motion_targets(const Animation& animation, const MotionView& view,
                                     const ChainOptions& chain_options)
{
    Result<MotionTargets> result;
    if (!check_view(animation, view, ViewRefusal{result}))
        return result;
    const int frames = animation.frames();
    auto refuse = [&](const std::string& option, const std::string& why) {
        ViewRefusal{result}(option, why);
        return result;
    };

    const Mat3 axes = card_axes(view.view, view.up);
    MotionTargets& targets = result.value;
    targets.chains = linkage_chains(animation, chain_options);
    if (view.auto_frames && view.first_frame == 0 && view.last_frame < 0)
        targets.window = best_frame_window(animation, targets.chains, axes.topRows<2>());
    const int first = targets.window.chosen ? targets.window.first : view.first_frame;
    const int last = targets.window.chosen ? targets.window.last
                     : view.last_frame < 0 ? frames - 1
                                           : view.last_frame;
    targets.first_frame = first;
    targets.last_frame = last;
    // A lone chain's travel is its motion (a hand on a line); a character's is a walk.
    const InPlace in_place(animation, view.up, last,
                           !view.keep_travel && targets.chains.size() >= 2);

    // The character's extent over the range, in the card's axes (before scale and placement):
    // every bone at every frame, and the skinned mesh at up to 32 frames.
    // The still nodes above the character's root (an armature node at the file's origin) are not
    // the character: counted, a walk filmed far from the origin shrank to a corner of the card.
    const std::vector<bool> above = above_character(animation);
    Eigen::AlignedBox3d box;
    double travel = 0.0;
    for (int f = first; f <= last; ++f) {
        const std::vector<Eigen::Isometry3d> pose = forward_kinematics(animation, f);
        const Vec3 back = in_place.travel(pose);
        travel = std::max(travel, back.norm());
        for (size_t b = 0; b < pose.size(); ++b)
            if (!above[b])
                box.extend(axes * (pose[b].translation() - back));
    }
    if (!animation.mesh.vertices.empty()) {
        const int stride = std::max(1, (last - first) / skinned_frames_for_extent);
        for (int f = first;; f = std::min(f + stride, last)) {
            for (const Vec3& v : in_place.mesh(f).vertices)
                box.extend(axes * v);
            if (f == last)
                break;
        }
    }
    const Vec3 extent = box.sizes();
    double scale = 0.0;
    if (view.scale) {
        scale = *view.scale;
    } else {
        const double room_x = 2.0 * view.card.depth * (1.0 - 2.0 * view.margin);
        const double room_y = view.card.width * (1.0 - 2.0 * view.margin);
        scale = std::numeric_limits<double>::infinity();
        if (extent.x() > 0.0)
            scale = std::min(scale, room_x / extent.x());
        if (extent.y() > 0.0)
            scale = std::min(scale, room_y / extent.y());
        if (!std::isfinite(scale) || !(scale > 0.0))
            return refuse("scale", "cannot be found: the character's projection is a point "
                                   "over the frame range (give scale)");
    }
    const Vec2 centre = view.centre ? *view.centre : Vec2(0.0, 0.5 * view.card.width);
    const Vec3 box_centre = box.center();
    // card = scale · (axes · p − box centre) + (centre, 0): the depth centre goes to z = 0.
    Eigen::Matrix4d to_card = Eigen::Matrix4d::Identity();
    to_card.topLeftCorner<3, 3>() = scale * axes;
    to_card.topRightCorner<3, 1>() = Vec3(centre.x(), centre.y(), 0.0) - scale * box_centre;
    targets.animation_to_card = to_card;
    targets.diagonal_mm = scale * extent.head<2>().norm();
    targets.travel_removed_mm = scale * travel;
    targets.in_place = in_place.on;

    auto card = [&](const Vec3& p) -> Vec3 {
        return to_card.topLeftCorner<3, 3>() * p + to_card.topRightCorner<3, 1>();
    };
    auto frame_at = [&](double s) { return first + s * double(last - first); };

    // Depth D (eq. 6.7) at the last frame: each chain's mean card z (its vertices, or its
    // bones without a mesh), normalised over the character's depth range.
    const std::vector<Eigen::Isometry3d> final_pose = in_place.pose(last);
    const ModelMesh final_mesh =
        animation.mesh.vertices.empty() ? ModelMesh{} : in_place.mesh(last);
    double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
    std::vector<double> mean_z;
    for (const LinkageChain& chain : targets.chains) {
        double sum = 0.0;
        int count = 0;
        if (!final_mesh.vertices.empty() && !chain.vertices.empty())
            for (int v : chain.vertices) {
                sum += card(final_mesh.vertices[v]).z();
                ++count;
            }
        else
            for (int b : chain.bones) {
                sum += card(final_pose[b].translation()).z();
                ++count;
            }
        mean_z.push_back(sum / count);
    }
    if (!final_mesh.vertices.empty())
        for (const Vec3& v : final_mesh.vertices) {
            z_lo = std::min(z_lo, card(v).z());
            z_hi = std::max(z_hi, card(v).z());
        }
    else
        for (const Eigen::Isometry3d& g : final_pose) {
            z_lo = std::min(z_lo, card(g.translation()).z());
            z_hi = std::max(z_hi, card(g.translation()).z());
        }

    // A turn next to a piece shorter than 3e-4 of the character's diagonal (0.06 mm on a 200 mm
    // character, under a laser's kerf) is capture jitter, not a bend the card could show: with
    // 1e-9, a 4511-frame BVH kept ~30000 samples per chain (split far below its frames, every
    // quarter turning > τangle) and its mapping took 169 s; now ~8000.
    const double still = 3e-4 * std::max(1.0, targets.diagonal_mm);
    for (size_t c = 0; c < targets.chains.size(); ++c) {
        const LinkageChain& chain = targets.chains[c];
        // The chain's root is the joint it hangs from: its first bone's parent, or that bone
        // for a chain at the skeleton's root.
        const int tip = chain.bones.back();
        const int first_parent = animation.bones[chain.bones.front()].parent;
        const int base = first_parent >= 0 ? first_parent : chain.bones.front();
        ChainPath path;
        path.s = adaptive_samples(
            [&](double s) -> Vec2 {
                return card(in_place.pose(frame_at(s))[tip].translation()).head<2>();
            },
            view.angle_tolerance, still, 16, view.min_intervals);
        for (double s : path.s) {
            const std::vector<Eigen::Isometry3d> pose = in_place.pose(frame_at(s));
            path.effector.push_back(card(pose[tip].translation()).head<2>());
            path.root.push_back(card(pose[base].translation()).head<2>());
        }
        path.depth = z_hi > z_lo ? (mean_z[c] - z_lo) / (z_hi - z_lo) : 0.5;
        targets.paths.push_back(std::move(path));
    }
    return result;
}

double path_spread(const std::vector<Vec2>& points)
{
    Vec2 mean = Vec2::Zero();
    for (const Vec2& a : points)
        mean += a;
    mean /= std::max<std::size_t>(1, points.size());
    double spread = 0;
    for (const Vec2& a : points)
        spread = std::max(spread, (a - mean).norm());
    return spread;
}

bool path_moves(const ChainPath& path, double diagonal_mm)
{
    return path_spread(path.effector) > still_path_fraction * diagonal_mm;
}

} // namespace popup
