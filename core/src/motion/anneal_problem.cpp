#include "anneal_problem.hpp"

#include <algorithm>
#include <cmath>

#include "motion_kinematics.hpp"
#include "motion_parameters.hpp"

namespace popup::motion {

namespace {

double rms_between(const ChainTarget& a, const ChainTarget& b, const Vec2& shift_a,
                   const Vec2& shift_b)
{
    auto at = [](const ChainTarget& t, double s) {
        const auto it = std::lower_bound(t.s.begin(), t.s.end(), s);
        if (it == t.s.begin())
            return t.target.front();
        if (it == t.s.end())
            return t.target.back();
        const std::size_t i = std::size_t(it - t.s.begin());
        const double span = t.s[i] - t.s[i - 1];
        const double u = span > 0 ? (s - t.s[i - 1]) / span : 1.0;
        return Vec2((1 - u) * t.target[i - 1] + u * t.target[i]);
    };
    std::vector<double> s = a.s;
    s.insert(s.end(), b.s.begin(), b.s.end());
    std::sort(s.begin(), s.end());
    if (s.empty())
        return 0.0;
    double sum = 0;
    for (double si : s)
        sum += (at(a, si) - shift_a - at(b, si) + shift_b).squaredNorm();
    return std::sqrt(sum / s.size());
}

} // namespace

double path_distance(const ChainTarget& a, const ChainTarget& b)
{
    return rms_between(a, b, Vec2::Zero(), Vec2::Zero());
}

double motion_distance(const ChainTarget& a, const ChainTarget& b)
{
    if (a.target.empty() || b.target.empty())
        return 0.0;
    return rms_between(a, b, a.target.back(), b.target.back());
}

std::vector<Vec2> printed_path(const ChainTarget& t)
{
    std::vector<Vec2> out;
    if (t.target.empty())
        return out;
    const Vec2 open = t.target.back();
    for (double si : t.s)
        out.push_back(Vec2(open.x() * std::sin(M_PI * si / 2), open.y()));
    return out;
}

std::vector<Vec2> carried_path(const Slot& slot, const ChainTarget& t)
{
    if (slot.printed)
        return printed_path(t);
    if (slot.chains.size() > 1 && slot.mechanism.kind() == MotionKind::rotation &&
        !t.target.empty()) {
        // A merged arm turns each part about the arm's hinge from its own open place.
        std::vector<Vec2> out;
        for (double si : t.s)
            out.push_back(
                rotation_carried_point(slot.mechanism, t.target.back(), M_PI * si).head<2>());
        return out;
    }
    std::vector<Vec2> out = achieved_path(slot.mechanism, t.s);
    if (slot.chains.size() > 1 && !t.target.empty()) {
        const Vec3 open = mechanism_point(slot.mechanism, M_PI);
        const Vec2 offset = t.target.back() - Vec2(open.x(), open.y());
        for (Vec2& q : out)
            q += offset;
    }
    return out;
}

double carried_error(const Slot& slot, const ChainTarget& t)
{
    const std::vector<Vec2> path = carried_path(slot, t);
    if (path.empty())
        return 0.0;
    double sum = 0;
    for (std::size_t k = 0; k < path.size(); ++k)
        sum += (path[k] - t.target[k]).squaredNorm();
    return std::sqrt(sum / double(path.size()));
}

CollisionVolume slot_volume(const AnnealProblem& p, const Slot& slot)
{
    if (slot.printed)
        return {};
    CollisionVolume v = collision_volume(slot.mechanism, p.volumes);
    if (slot.chains.size() < 2 || slot.mechanism.kind() == MotionKind::rotation)
        return v;
    const Vec3 open = mechanism_point(slot.mechanism, M_PI);
    std::vector<Vec3> offsets;
    for (int j : slot.chains) {
        const ChainTarget& t = p.chains[j];
        if (!t.target.empty())
            offsets.emplace_back(t.target.back().x() - open.x(), t.target.back().y() - open.y(), 0);
    }
    carry_along(v, offsets);
    return v;
}

void prepare_alike(AnnealProblem& p)
{
    const std::size_t n = p.chains.size();
    p.alike.assign(n, std::vector<bool>(n, false));
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t k = 0; k < n; ++k)
            p.alike[j][k] =
                j == k ||
                (motion_distance(p.chains[j], p.chains[k]) <= p.alike_fraction * p.diagonal &&
                 !p.chains[j].target.empty() && !p.chains[k].target.empty() &&
                 (p.chains[j].target.back() - p.chains[k].target.back()).norm() <=
                     p.beside_fraction * p.diagonal &&
                 (p.still.empty() || p.still[j] == p.still[k]));
}

double slot_cost(const AnnealProblem& p, const Slot& slot)
{
    // E_d charges the mechanisms that set a height (v-box, diagonal nose, floating layer). The
    // rotation arm and the extruding patch lie flat: the thesis stands them on a floating layer
    // at the chain's depth, so their disparity is not charged (docs/DESIGN.md).
    const MotionKind kind = slot.mechanism.kind();
    const bool flat =
        !slot.printed && (kind == MotionKind::rotation || kind == MotionKind::horizontal);
    const double H =
        slot.printed ? 0.0 : std::clamp(mechanism_height(slot.mechanism) / p.h_max, 0.0, 1.0);
    double e = 0;
    for (int j : slot.chains) {
        const ChainTarget& t = p.chains[j];
        e += t.weight * (p.motion_weight * carried_error(slot, t) / p.diagonal +
                         (flat ? 0.0 : p.depth_weight * std::abs(t.depth - H)));
    }
    return e;
}

double state_cost(const AnnealProblem& p, const AnnealState& s)
{
    double e = 0;
    for (const Slot& slot : s.slots)
        e += slot_cost(p, slot);
    return e;
}

double state_motion_error(const AnnealProblem& p, const AnnealState& s)
{
    double e = 0;
    for (const Slot& slot : s.slots)
        for (int j : slot.chains)
            e += p.chains[j].weight * carried_error(slot, p.chains[j]) / p.diagonal;
    return e;
}

std::vector<SlotCollision> state_collisions(const AnnealProblem& p, const AnnealState& s)
{
    std::vector<CollisionVolume> v;
    for (const Slot& slot : s.slots)
        v.push_back(slot_volume(p, slot));
    std::vector<SlotCollision> out;
    for (int i = 0; i < int(v.size()); ++i)
        for (int j = i + 1; j < int(v.size()); ++j) {
            const double d = collision_depth(v[i], v[j]);
            if (d > 0)
                out.push_back({i, j, d});
        }
    return out;
}

double state_collision(const AnnealProblem& p, const AnnealState& s)
{
    double d = 0;
    for (const SlotCollision& c : state_collisions(p, s))
        d += c.depth;
    return d;
}

double chain_weight(const AnnealProblem& p, const Slot& s)
{
    double w = 0;
    for (int j : s.chains)
        w += p.chains[j].weight;
    return w;
}

double printed_error(const AnnealProblem& p, int j)
{
    Slot printed;
    printed.printed = true;
    printed.chains = {j};
    return carried_error(printed, p.chains[j]);
}

} // namespace popup::motion
