#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fitting/synthetic_models.hpp"
#include "popup/fitting/fit_design.hpp"
#include "popup/simulation/check_validity.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

/// The scale fit_design must use (docs/MATH.md, Fitting): closed, a box fold reaches its height
/// plus its half depth from the fold, and its end panels stand out of its ends by its half depth:
/// the length plus the depth fits the card's usable width, height plus half depth a page's.
double expected_scale(double length, double half_depth, double height, const FitOptions& o)
{
    return std::min(o.card_width * (1 - 2 * o.margin) / (length + 2 * half_depth),
                    o.card_depth * (1 - 2 * o.margin) / (height + half_depth));
}

/// Distance from x to the nearest patch of the scaffold (planar polygons, computed here).
double distance_to_scaffold(const Scaffold& s, const Vec3& x)
{
    double best = 1e300;
    for (const Patch& p : s.patches) {
        const auto& o = p.outer;
        Vec3 n = Vec3::Zero(); // Newell
        for (size_t i = 0; i < o.size(); ++i)
            n += o[i].cross(o[(i + 1) % o.size()]);
        n.normalize();
        const double off = (x - o[0]).dot(n);
        const Vec3 q = x - off * n;
        bool inside = true;
        double edge = 1e300;
        for (size_t i = 0; i < o.size(); ++i) {
            const Vec3 a = o[i], b = o[(i + 1) % o.size()];
            if ((b - a).cross(q - a).dot(n) < -1e-9)
                inside = false; // convex patches: outside one edge
            const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
            edge = std::min(edge, (a + t * (b - a) - q).norm());
        }
        best = std::min(best, inside ? std::abs(off) : std::hypot(off, edge));
    }
    return best;
}

/// Mean distance from points spread on the faces of the box [lo, hi] to the scaffold.
double mean_box_to_scaffold(const Scaffold& s, const Vec3& lo, const Vec3& hi)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    double sum = 0;
    int n = 0;
    const Vec3 size = hi - lo;
    const double areas[3] = {size.y() * size.z(), size.x() * size.z(), size.x() * size.y()};
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int count = int(4000 * areas[axis] / (areas[0] + areas[1] + areas[2]));
            for (int k = 0; k < count; ++k) {
                Vec3 p = lo + Vec3(u(rng) * size.x(), u(rng) * size.y(), u(rng) * size.z());
                p[axis] = side ? hi[axis] : lo[axis];
                sum += distance_to_scaffold(s, p);
                ++n;
            }
        }
    return sum / n;
}

const FittedMechanism* find_type(const FitResult& r, const std::string& type, int nth = 0)
{
    for (const auto& m : r.mechanisms)
        if (m.type == type && nth-- == 0)
            return &m;
    return nullptr;
}

std::string describe(const FitResult& r)
{
    std::string s;
    for (const auto& m : r.mechanisms) {
        s += m.name + " " + m.type + " on " + m.host + ":";
        for (const auto& [k, v] : m.parameters)
            s += " " + k + "=" + std::to_string(v);
        s += "\n";
    }
    for (const auto& rp : r.repairs)
        s += "repair " + rp.mechanism + " " + rp.action + ": " + rp.reason + "\n";
    return s;
}

} // namespace

TEST(FitDesign, CuboidIsOneBoxFoldWhoseDesignStateIsTheCuboid)
{
    const FitOptions o;
    const auto result = fit_design(cuboid_model(), o);
    ASSERT_TRUE(result.ok) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    const FitResult& r = result.value;
    ASSERT_EQ(r.mechanisms.size(), 1u) << describe(r);
    const FittedMechanism& box = r.mechanisms[0];
    EXPECT_EQ(box.type, "box_fold");
    EXPECT_EQ(box.host, "central fold");
    EXPECT_TRUE(r.valid);
    EXPECT_TRUE(check_validity(r.scaffold).valid());

    // 40 x 120 x 30: the fold runs along the 120, x is the 40 across it.
    const double s = expected_scale(120, 20, 30, o);
    const double length = 120 * s, depth = 20 * s, height = 30 * s;
    const auto& q = box.parameters;
    EXPECT_NEAR(q.at("width"), length, 0.02 * length);
    EXPECT_NEAR(q.at("depth_ground"), depth, 0.02 * 2 * depth);
    EXPECT_NEAR(q.at("depth_backdrop"), depth, 0.02 * 2 * depth);
    EXPECT_NEAR(q.at("height"), height, 0.02 * height);
    EXPECT_NEAR(q.at("offset"), (o.card_width - length) / 2, 0.02 * length);

    // The design state is the cuboid: its surface lies on the patches.
    const Vec3 lo(-depth, (o.card_width - length) / 2, 0), hi(depth, lo.y() + length, height);
    const double diagonal = (hi - lo).norm();
    EXPECT_LE(mean_box_to_scaffold(r.scaffold, lo, hi), 0.005 * diagonal);
}

TEST(FitDesign, TentPrismIsATentFold)
{
    const FitOptions o;
    const auto result = fit_design(tent_model(), o);
    ASSERT_TRUE(result.ok) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    const FitResult& r = result.value;
    ASSERT_EQ(r.mechanisms.size(), 1u) << describe(r);
    const FittedMechanism* tent = find_type(r, "tent_fold");
    ASSERT_TRUE(tent) << describe(r);
    EXPECT_TRUE(r.valid);
    const double s = expected_scale(110, 30, 36, o);
    const auto& q = tent->parameters;
    EXPECT_NEAR(q.at("width"), 110 * s, 0.02 * 110 * s);
    EXPECT_NEAR(q.at("foot"), 30 * s, 0.02 * 60 * s);
    EXPECT_NEAR(q.at("foot_backdrop"), 30 * s, 0.02 * 60 * s);
    EXPECT_NEAR(q.at("slope"), std::hypot(30, 36) * s, 0.02 * 36 * s);
}
