#pragma once
#include <string>
#include <vector>

#include "popup/geometry/pose.hpp"

namespace popup {

enum class PatchRole { ground, backdrop, support, top, front, back, tab, other };

const char* to_string(PatchRole role);
/// Parses a role name; returns false for an unknown name.
bool parse_patch_role(const std::string& name, PatchRole& role);

/// A planar polygon of paper. Loops are stored in design-state world coordinates (mm); the
/// local 2D frame (origin, u, v, normal = u x v) is derived from them.
struct Patch {
    int id = 0;
    std::string name;
    PatchRole role = PatchRole::other;
    Loop3 outer;              ///< counter-clockwise seen from the normal side
    std::vector<Loop3> holes; ///< clockwise seen from the normal side

    Vec3 origin = Vec3::Zero(); ///< local frame, filled by `derive_frame`
    Vec3 u = Vec3::UnitX();
    Vec3 v = Vec3::UnitY();
    Vec3 normal = Vec3::UnitZ();

    /// Fits the plane of the outer loop and sets origin/u/v/normal (normal by Newell's method,
    /// so it follows the winding). Returns the largest distance of any vertex from that plane.
    double derive_frame();
    Vec2 to_local(const Vec3& x) const;
    Loop2 outer_local() const;
    std::vector<Loop2> holes_local() const;
    Vec3 centroid() const;
    /// x lies in the patch's plane and inside or on its outline (not in a hole), within tol.
    /// Needs derive_frame().
    bool contains(const Vec3& x, double tol) const;
    double area() const;
};

/// How every message names a patch: "patch 5 (BoxFold.TG)", or "patch 5" when it has no name.
/// The Workbench replaces this exact text with the part's maker title (patch_titles.py).
std::string patch_subject(const Patch& patch);

} // namespace popup
