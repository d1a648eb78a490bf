#include "fold_directions.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace popup::sheets {

std::vector<double> sweep_angles(const Scaffold& s, int count)
{
    std::vector<double> angles;
    for (int k = 0; k < count; ++k)
        angles.push_back(s.design_angle * (1.0 - double(k) / (count - 1)));
    for (double degrees : {150.0, 90.0, 30.0})
        angles.push_back(degrees * M_PI / 180.0);
    std::sort(angles.begin(), angles.end(), std::greater<double>());
    angles.erase(std::unique(angles.begin(), angles.end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                 angles.end());
    return angles;
}

BendSamples sample_bends(const Scaffold& s, const std::vector<FoldState>& sweep)
{
    BendSamples samples;
    samples.states.emplace_back(s.patches.size(), Pose{});
    for (const FoldState& state : sweep)
        samples.states.push_back(state.poses);
    return samples;
}

namespace {

// Which way the point `on_b` of patch b (design state) turns away from patch a about the hinge
// through `on_hinge`, seen from `normal_a`: the strongest lift over the samples decides.
FoldDirection turn_toward(const Scaffold& s, const BendSamples& samples, int a,
                          const Vec3& normal_a, int b, const Vec3& on_b, const Vec3& on_hinge,
                          bool& bent)
{
    const int ia = s.patch_index(a), ib = s.patch_index(b);
    const double reach = std::max((on_b - on_hinge).norm(), 1e-12);
    double strongest = 0.0;
    for (const std::vector<Pose>& poses : samples.states) {
        const Pose& pa = poses[ia];
        const Vec3 lift = poses[ib].apply(on_b) - pa.apply(on_hinge);
        const double side = lift.dot(pa.rotation * normal_a) / reach;
        if (std::abs(side) > std::abs(strongest))
            strongest = side;
    }
    bent = std::abs(strongest) > 1e-6;
    return strongest < 0 ? FoldDirection::mountain : FoldDirection::valley;
}

} // namespace

FoldDirection bend_direction(const Scaffold& s, const BendSamples& samples, int a,
                             const Vec3& normal_a, int b, const Vec3& on_hinge, bool& bent)
{
    return turn_toward(s, samples, a, normal_a, b, s.patches[s.patch_index(b)].centroid(), on_hinge,
                       bent);
}

FoldDirection tab_direction(const Scaffold& s, const BendSamples& samples, const Hinge& h,
                            const LocalPiece& carrier, int carrier_patch, const LocalPiece& target,
                            int target_patch, const Vec2& glue_point, bool& bent)
{
    // A unit step from the joint's middle across it within the target patch, toward the glue.
    const Vec3 middle = 0.5 * (h.from + h.to);
    Vec3 across = s.find_patch(target_patch)->normal.cross(h.to - h.from).normalized();
    const Vec2 flat_middle = target.flat_point(s, target_patch, middle);
    if ((target.flat_point(s, target_patch, middle + across) - flat_middle)
            .dot(glue_point - flat_middle) < 0)
        across = -across;
    return turn_toward(s, samples, carrier_patch, carrier.printed_normal(s, carrier_patch),
                       target_patch, middle + across, middle, bent);
}

FoldDirection drawn_direction(const Scaffold& s, const BendSamples& samples, const Hinge& h,
                              const Vec3& printed_a, bool& unspecified)
{
    bool bent = false;
    unspecified = false;
    const FoldDirection bends =
        bend_direction(s, samples, h.patch_a, printed_a, h.patch_b, h.from, bent);
    if (bent)
        return bends;
    if (h.direction == FoldDirection::unspecified) {
        unspecified = true;
        return FoldDirection::valley;
    }
    const bool flipped = printed_a.dot(s.find_patch(h.patch_a)->normal) < 0;
    if (!flipped)
        return h.direction;
    return h.direction == FoldDirection::valley ? FoldDirection::mountain : FoldDirection::valley;
}

} // namespace popup::sheets
