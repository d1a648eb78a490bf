#include "fold_directions.hpp"

#include <cmath>

namespace popup::sheets {

BendSamples sample_bends(const Scaffold& s, const std::vector<FoldState>& sweep)
{
    BendSamples samples;
    samples.states.emplace_back(s.patches.size(), Pose{});
    for (const FoldState& state : sweep)
        samples.states.push_back(state.poses);
    return samples;
}

FoldDirection bend_direction(const Scaffold& s, const BendSamples& samples, int a,
                             const Vec3& normal_a, int b, const Vec3& on_hinge, bool& bent)
{
    const int ia = s.patch_index(a), ib = s.patch_index(b);
    const Vec3 centre_b = s.patches[ib].centroid();
    const double reach = std::max((centre_b - on_hinge).norm(), 1e-12);
    double strongest = 0.0;
    for (const std::vector<Pose>& poses : samples.states) {
        const Pose& pa = poses[ia];
        const Vec3 lift = poses[ib].apply(centre_b) - pa.apply(on_hinge);
        const double side = lift.dot(pa.rotation * normal_a) / reach;
        if (std::abs(side) > std::abs(strongest))
            strongest = side;
    }
    bent = std::abs(strongest) > 1e-6;
    return strongest < 0 ? FoldDirection::mountain : FoldDirection::valley;
}

} // namespace popup::sheets
