#include <algorithm>
#include <cmath>

#include "popup/motion/animation.hpp"

namespace popup {

namespace {

/// Between two rigid transforms: slerp of the rotations, lerp of the translations.
Eigen::Isometry3d blend(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double t)
{
    const Eigen::Quaterniond qa(a.linear()), qb(b.linear());
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = qa.slerp(t, qb).toRotationMatrix();
    out.translation() = (1.0 - t) * a.translation() + t * b.translation();
    return out;
}

} // namespace

std::vector<Eigen::Isometry3d> forward_kinematics(const Animation& animation, double frame)
{
    const int frames = animation.frames();
    const int n = int(animation.bones.size());
    std::vector<Eigen::Isometry3d> global(n, Eigen::Isometry3d::Identity());
    if (frames == 0)
        return global;
    // Outside the range a frame is the nearest end; inside, between its two neighbours.
    const double at = std::clamp(std::isfinite(frame) ? frame : 0.0, 0.0, double(frames - 1));
    const int lo = std::min(int(std::floor(at)), frames - 1);
    const int hi = std::min(lo + 1, frames - 1);
    const double t = at - lo;
    for (int b = 0; b < n; ++b) {
        const Eigen::Isometry3d local =
            t == 0.0 ? animation.local[lo][b]
                     : blend(animation.local[lo][b], animation.local[hi][b], t);
        const int parent = animation.bones[b].parent;
        global[b] = parent >= 0 ? global[parent] * local : local;
    }
    return global;
}

} // namespace popup
