#include "popup/model/scaffold.hpp"

#include <algorithm>
#include <cmath>

namespace popup {

const char* to_string(FoldDirection direction)
{
    switch (direction) {
    case FoldDirection::valley:
        return "valley";
    case FoldDirection::mountain:
        return "mountain";
    default:
        return "unspecified";
    }
}

const char* to_string(JointKind kind)
{
    return kind == JointKind::tab ? "tab" : "fold";
}

const Patch* Scaffold::find_patch(int id) const
{
    const int i = patch_index(id);
    return i < 0 ? nullptr : &patches[i];
}

int Scaffold::patch_index(int id) const
{
    for (size_t i = 0; i < patches.size(); ++i)
        if (patches[i].id == id)
            return int(i);
    return -1;
}

double Scaffold::size() const
{
    Eigen::AlignedBox3d box;
    for (const Patch& p : patches)
        for (const Vec3& x : p.outer)
            box.extend(x);
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

double shortest_fold(const Scaffold& scaffold)
{
    return 1e-5 * std::max(scaffold.size(), 1.0);
}

namespace {
// The ground turns about the central fold (the y axis) by half the change of the fold angle.
Pose base_pose(double half_turn)
{
    Pose p;
    p.rotation = axis_angle(Vec3::UnitY(), half_turn);
    return p;
}
} // namespace

Pose ground_pose(const Scaffold& scaffold, double theta)
{
    return base_pose(0.5 * (theta - scaffold.design_angle));
}

Pose backdrop_pose(const Scaffold& scaffold, double theta)
{
    return base_pose(-0.5 * (theta - scaffold.design_angle));
}

} // namespace popup
