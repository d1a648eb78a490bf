// The frame window a card can show (docs/MATH.md, "The frame window").
#include "popup/motion/frame_window.hpp"

#include <algorithm>
#include <cmath>

namespace popup {

namespace {

constexpr int kLookedAt = 120;   ///< frames looked at, evenly spread over the take
constexpr double kBetter = 1.1;  ///< a window must beat the whole take by a tenth
constexpr double kRetreat = 2.0; ///< a retreat costs twice what the chord gains

/// Per chain (that hangs from another): its tip against its hang joint, projected, at each
/// looked-at frame.
std::vector<std::vector<Vec2>> relative_tips(const Animation& animation,
                                             const std::vector<LinkageChain>& chains,
                                             const Eigen::Matrix<double, 2, 3>& projection,
                                             const std::vector<int>& frames)
{
    std::vector<std::vector<Vec2>> tips(chains.size());
    for (int f : frames) {
        const std::vector<Eigen::Isometry3d> pose = forward_kinematics(animation, double(f));
        for (size_t c = 0; c < chains.size(); ++c) {
            const int from = animation.bones[chains[c].bones.front()].parent;
            if (from < 0)
                continue;
            const Vec3 tip = pose[chains[c].bones.back()].translation() - pose[from].translation();
            tips[c].push_back(projection * tip);
        }
    }
    return tips;
}

/// chord − 2 · retreat of one path over looked-at frames i..j: the retreat is the largest step
/// back along the chord from the farthest point reached so far.
double followable(const std::vector<Vec2>& path, int i, int j)
{
    const Vec2 chord = path[j] - path[i];
    const double length = chord.norm();
    if (!(length > 0.0))
        return 0.0;
    const Vec2 along = chord / length;
    double farthest = 0.0, retreat = 0.0;
    for (int k = i; k <= j; ++k) {
        const double progress = (path[k] - path[i]).dot(along);
        farthest = std::max(farthest, progress);
        retreat = std::max(retreat, farthest - progress);
    }
    return length - kRetreat * retreat;
}

} // namespace

FrameWindow best_frame_window(const Animation& animation, const std::vector<LinkageChain>& chains,
                              const Eigen::Matrix<double, 2, 3>& projection, double min_seconds)
{
    FrameWindow window;
    const int count = animation.frames();
    window.last = std::max(0, count - 1);
    if (count < 3)
        return window;
    const int looked = std::min(count, kLookedAt);
    std::vector<int> frames;
    for (int k = 0; k < looked; ++k)
        frames.push_back(int(std::lround(double(k) * (count - 1) / (looked - 1))));
    const std::vector<std::vector<Vec2>> tips =
        relative_tips(animation, chains, projection, frames);
    auto score = [&](int i, int j) {
        double sum = 0.0;
        for (size_t c = 0; c < chains.size(); ++c)
            if (!tips[c].empty())
                sum += chains[c].weight * followable(tips[c], i, j);
        return sum;
    };
    window.whole_score = window.score = score(0, looked - 1);
    const double duration = animation.frame_times_s.back() - animation.frame_times_s.front();
    const int shortest = std::max(1, int(std::ceil(min_seconds / duration * (looked - 1))));
    int best_i = -1, best_j = -1;
    double best = 0.0;
    for (int i = 0; i + shortest < looked; ++i)
        for (int j = i + shortest; j < looked; ++j) {
            const double s = score(i, j), tie = 1e-12 * std::abs(best);
            // Ties: the longer window, then the earlier (looked at in that order).
            if (best_i < 0 || s > best + tie || (s >= best - tie && j - i > best_j - best_i)) {
                best = s;
                best_i = i;
                best_j = j;
            }
        }
    if (best_i >= 0 && best > kBetter * window.whole_score && (best_i > 0 || best_j < looked - 1)) {
        window.first = frames[size_t(best_i)];
        window.last = frames[size_t(best_j)];
        window.score = best;
        window.chosen = true;
    }
    return window;
}

} // namespace popup
