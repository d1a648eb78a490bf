#pragma once
#include <string>
#include <vector>

#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

/// An outline a patch is cut to: an outer loop and optional holes (either winding), in the
/// patch's profile frame (see ProfileFrame), millimetres at the design state.
struct Profile {
    std::string name = "profile"; ///< what messages call it (a sketch's label, "silhouette")
    Loop2 outer;
    std::vector<Loop2> holes;
};

/// A patch's profile frame (docs/DESIGN.md, "Profiles"): the origin is the midpoint of the
/// patch's base hinge, u runs along that hinge, v across the patch (the patch lies at v >= 0),
/// and (u, v, normal) is right-handed, so an outline drawn in (u, v) is what a viewer of the
/// printed side sees. The base hinge is the patch's first hinge (scaffold order, which is the
/// order generators add them) joining it to an older patch (smaller id): a mechanism part's
/// hinge with its host, or with the part it was built from. Only the hinge's midpoint and
/// direction matter, so a Width edit keeps an outline centred on it.
struct ProfileFrame {
    int patch = -1;
    int hinge = -1; ///< id of the base hinge
    Vec3 origin = Vec3::Zero();
    Vec3 u = Vec3::UnitX();
    Vec3 v = Vec3::UnitY();
    Vec3 normal = Vec3::UnitZ();

    Vec2 to_frame(const Vec3& x) const
    {
        const Vec3 d = x - origin;
        return {d.dot(u), d.dot(v)};
    }
    Vec3 to_world(const Vec2& q) const { return origin + q.x() * u + q.y() * v; }
};

/// The profile frame of patch `patch_id`; fails (unknown_patch, bad_profile) when the scaffold
/// has no such patch or the patch has no hinge to measure from.
Result<ProfileFrame> profile_frame(const Scaffold& scaffold, int patch_id);

/// The profile with repeated and closing points dropped, checked: every loop has 3 distinct
/// points or more, finite coordinates within ±1e6 mm, an area, no edge crossing another, and
/// holes inside the outer loop. Errors are bad_profile and name the profile, the loop and the
/// point.
Result<Profile> checked_profile(const Profile& profile);

} // namespace popup
