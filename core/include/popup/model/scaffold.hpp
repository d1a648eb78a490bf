#pragma once
#include <string>
#include <vector>

#include "popup/model/patch.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// Intended direction of a fold, seen from the patches' normal (printed) side: a valley brings
/// the two normal sides together, a mountain takes them apart. Needed for folds that are flat at
/// the design state, where the motion can branch either way.
enum class FoldDirection { unspecified, valley, mountain };

const char* to_string(FoldDirection direction);

/// A fold is a crease inside one sheet of paper; a tab joint is where two sheets meet, joined by
/// a glue tab along the hinge. They move alike; the cutting sheets tell them apart.
enum class JointKind { fold, tab };

const char* to_string(JointKind kind);

/// A fold: a segment lying on the boundary or inside of both patches.
struct Hinge {
    int id = 0;
    int patch_a = 0;
    int patch_b = 0;
    Vec3 from = Vec3::Zero(); ///< design-state world coordinates (mm)
    Vec3 to = Vec3::Zero();
    FoldDirection direction = FoldDirection::unspecified;
    JointKind kind = JointKind::fold;
};

/// Two patches rigidly joined (a glue tab): they move as one body.
struct Glue {
    int patch_a = 0;
    int patch_b = 0;
};

/// A slit cut in one patch that another patch passes through (thesis §4.3.1): the slit's line
/// stays in the plane of the patch through it, which may slide along it and turn about it.
struct Slit {
    int id = 0;
    int patch_cut = 0;     ///< the patch the slit is cut in; the segment lies on it
    int patch_through = 0; ///< the patch passing through; the segment lies in its plane
    Vec3 from = Vec3::Zero();
    Vec3 to = Vec3::Zero();
};

/// Patches, hinges and glue joints of a pop-up at its design state, in the frame of thesis §4.3:
/// y along the central fold, z bisecting the fold angle, x toward the ground.
struct Scaffold {
    std::string name = "scaffold";
    std::vector<Patch> patches;
    std::vector<Hinge> hinges;
    std::vector<Glue> glue;
    std::vector<Slit> slits;
    int ground = -1;   ///< id of the ground base patch (x > 0 at 180°)
    int backdrop = -1; ///< id of the backdrop base patch (x < 0 at 180°)
    double design_angle = 3.14159265358979323846; ///< fold angle of the stored state (radians)
    double paper_thickness = 0.2;                 ///< mm

    const Patch* find_patch(int id) const;
    int patch_index(int id) const; ///< -1 when absent
    /// Diagonal of the design-state bounding box (mm): the scale of every tolerance.
    double size() const;
};

/// The shortest fold a mechanism may make on `scaffold` (mm): 1e-5 of the model's size, ten times
/// the simulator's tolerance. Shorter, a fold's direction is lost in round-off.
double shortest_fold(const Scaffold& scaffold);

/// Checks the scaffold's own consistency (ids, planarity, finite numbers, hinges lying on both
/// patches, base patches present) and derives every patch frame. Errors name the item.
Result<Scaffold> validate_scaffold(Scaffold scaffold);

/// World pose of the ground and the backdrop at fold angle `theta`, relative to the design state.
Pose ground_pose(const Scaffold& scaffold, double theta);
Pose backdrop_pose(const Scaffold& scaffold, double theta);

} // namespace popup
