// Collision volumes: every closed-form vertex at 1000 fold angles inside its piece's box (and on
// its piece's side), the four mechanisms the synthetic rigs are made of (valid together by the
// simulator) apart, the depth's size from the boxes' construction, and every patch the
// generators build, posed by the simulator, inside its volume.
// The separating-axis test against a brute-force intersection test that shares nothing with it:
// two convex boxes meet iff a corner of one lies in the other or an edge of one crosses the other
// (Liang–Barsky clipping of the edge against the other box's slabs).
#include <gtest/gtest.h>

#include <random>

#include "motion/collision_volume.hpp"
#include "motion/motion_feasibility.hpp"
#include "motion_fixtures.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::motion {
namespace {

using testing::build;
using testing::Built;
using testing::samples;

OrientedBox random_box(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    OrientedBox b;
    b.centre = Vec3(u(rng), u(rng), u(rng)) * 3.0;
    b.half = Vec3(0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng)), 0.2 + std::abs(u(rng))) * 1.5;
    const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
    b.axes = Eigen::AngleAxisd(M_PI * u(rng), axis).toRotationMatrix();
    return b;
}

bool inside(const OrientedBox& b, const Vec3& x)
{
    const Vec3 local = b.axes.transpose() * (x - b.centre);
    return (local.cwiseAbs() - b.half).maxCoeff() <= 0;
}

bool segment_meets(const OrientedBox& b, const Vec3& p, const Vec3& q)
{
    const Vec3 a = b.axes.transpose() * (p - b.centre), d = b.axes.transpose() * (q - p);
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-15) {
            if (std::abs(a[i]) > b.half[i])
                return false;
            continue;
        }
        double ta = (-b.half[i] - a[i]) / d[i], tb = (b.half[i] - a[i]) / d[i];
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1)
            return false;
    }
    return true;
}

bool brute_force_meet(const OrientedBox& a, const OrientedBox& b)
{
    const auto ca = a.corners(), cb = b.corners();
    for (const Vec3& x : ca)
        if (inside(b, x))
            return true;
    for (const Vec3& x : cb)
        if (inside(a, x))
            return true;
    // Edges: corners k and k ^ (1 << axis).
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (k & bit)
                continue;
            if (segment_meets(b, ca[k], ca[k | bit]) || segment_meets(a, cb[k], cb[k | bit]))
                return true;
        }
    return false;
}

TEST(CollisionVolume, SeparatingAxesAgreeWithBruteForceOnRandomBoxPairs)
{
    std::mt19937_64 rng(42);
    int meeting = 0, apart = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const OrientedBox a = random_box(rng), b = random_box(rng);
        const bool sat = overlap_depth(a, b) > 0;
        const bool brute = brute_force_meet(a, b);
        ASSERT_EQ(sat, brute) << "trial " << trial;
        (brute ? meeting : apart)++;
    }
    EXPECT_GT(meeting, 500); // both verdicts well represented
    EXPECT_GT(apart, 500);
}

TEST(CollisionVolume, DepthOfTwoAxisAlignedBoxesIsTheirSmallestOverlap)
{
    OrientedBox a, b;
    a.half = Vec3(2, 3, 4);
    b.half = Vec3(1, 1, 1);
    b.centre = Vec3(2.5, 0, 0); // x overlap: 2 + 1 − 2.5 = 0.5; y: 4, z: 5
    EXPECT_NEAR(overlap_depth(a, b), 0.5, 1e-12);
    b.centre = Vec3(2.5, 3.8, 0); // y overlap 0.2
    EXPECT_NEAR(overlap_depth(a, b), 0.2, 1e-12);
    b.centre = Vec3(3.5, 0, 0); // touching faces: separate
    EXPECT_EQ(overlap_depth(a, b), 0.0);
}

constexpr MotionKind all_kinds[] = {MotionKind::vertical, MotionKind::diagonal,
                                    MotionKind::horizontal, MotionKind::rotation,
                                    MotionKind::stationary};

// The known mechanisms of tools/make_animations.py (MECHANISMS), which rig_four animates at once.
std::vector<MotionMechanism> rig_four_mechanisms()
{
    return {rotation_mechanism(168, 40, 22, 32), vertical_mechanism(106, 25, 35, 35 * M_PI / 180),
            horizontal_mechanism(150, 14, 40, 15, 70),
            diagonal_mechanism(40, 60, 45 * M_PI / 180, 55, 6, 12, 30, 12)};
}

TEST(CollisionVolume, EveryClosedFormVertexAt1000AnglesLiesInItsPiecesBox)
{
    // Independent of how the boxes are made: the closed forms sampled 1000 times (the volume
    // samples 17 angles), each vertex, x divided by sin(θ/2), tested against its piece's box in
    // the band holding θ (the box and the padded hull share the samples and the pads).
    const CardParams card = testing::a4_card();
    std::vector<MotionMechanism> mechanisms = rig_four_mechanisms();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> scale(0.7, 1.3);
    for (MotionKind kind : all_kinds) {
        const MotionMechanism sample = testing::sample_mechanism(kind);
        mechanisms.push_back(sample);
        for (int tries = 0, kept = 0; tries < 200 && kept < 6; ++tries) {
            MotionMechanism m = sample;
            for (int i = 0; i < parameter_count(kind); ++i)
                parameter(m, i) *= scale(rng);
            if (infeasibility(m, card).empty()) {
                mechanisms.push_back(m);
                ++kept;
            }
        }
    }
    ASSERT_GT(mechanisms.size(), 4u + 5u * 4);
    const VolumeOptions options;
    for (const MotionMechanism& m : mechanisms) {
        const CollisionVolume v = collision_volume(m, options);
        const std::size_t pieces = v.sides.size();
        int outside = 0, wrong_side = 0;
        double worst = 0;
        for (int j = 1; j < 1000; ++j) {
            // Closed (θ = 0) the paper lies flat and the volume's frame, x / sin(θ/2), is a limit.
            const double theta = M_PI * j / 999;
            const int band = std::min(options.bands - 1, int(theta / (M_PI / options.bands)));
            const std::vector<MechanismPart> parts = mechanism_parts(m, theta);
            ASSERT_EQ(parts.size(), pieces);
            for (std::size_t i = 0; i < pieces; ++i)
                for (const Vec3& x : parts[i].vertices) {
                    const Vec3 mapped(x.x() / std::sin(theta / 2), x.y(), x.z());
                    const std::size_t at = band * pieces + i;
                    const OrientedBox& box = v.aligned[at];
                    double out = ((mapped - box.centre).cwiseAbs() - box.half).maxCoeff();
                    // And within the padded hull's shadow on the axes the depth tests: the
                    // piece's normal, and its edges crossed with it.
                    std::vector<Vec3> axes{v.normals[at]};
                    for (int e = v.edge_first[at]; e < v.edge_first[at + 1]; ++e)
                        axes.push_back(v.normals[at].cross(v.edges[e]));
                    for (const Vec3& axis : axes) {
                        if (axis.norm() < 1e-9)
                            continue;
                        const Vec3 n = axis.normalized();
                        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
                        for (int q = v.first[at]; q < v.first[at + 1]; ++q) {
                            const double t = n.dot(Vec3(v.xs[q], v.ys[q], v.zs[q]));
                            lo = std::min(lo, t);
                            hi = std::max(hi, t);
                        }
                        const double pad = n.cwiseAbs().dot(v.pad[at]);
                        out = std::max(
                            out, std::max(lo - pad - n.dot(mapped), n.dot(mapped) - hi - pad));
                    }
                    worst = std::max(worst, out);
                    outside += out > 1e-9;
                    wrong_side += v.sides[i] * x.x() < -1e-9;
                }
        }
        EXPECT_EQ(outside, 0) << to_string(m.kind()) << " offset = " << fold_offset(m) << ": "
                              << worst << " mm out";
        EXPECT_EQ(wrong_side, 0) << to_string(m.kind());
    }
}

TEST(CollisionVolume, TheRigsFourMechanismsAreValidTogetherAndTheirVolumesApart)
{
    CardParams params;
    params.width = 210;
    params.depth = 148;
    Scaffold card = make_card(params).value;
    const std::vector<MotionMechanism> four = rig_four_mechanisms();
    std::vector<FittedMechanism> rows;
    for (std::size_t i = 0; i < four.size(); ++i)
        ASSERT_TRUE(
            build_mechanism(card, central_fold(card), four[i], "m" + std::to_string(i), rows).ok);
    ASSERT_TRUE(check_validity(card).valid()); // the simulator: they fit together
    std::vector<CollisionVolume> v;
    for (const MotionMechanism& m : four)
        v.push_back(collision_volume(m));
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j)
            EXPECT_EQ(collision_depth(v[i], v[j]), 0.0)
                << to_string(four[i].kind()) << " and " << to_string(four[j].kind());
}

TEST(CollisionVolume, DepthOfTwoCopiesAlongTheFoldIsTheirOverlapAlongIt)
{
    // Two copies of an extruding patch d apart along the fold. Every piece has edges along the
    // fold and its vertices keep their y, so along y each piece's box is exactly [y0, y0 + width]
    // padded by the clearance: the copies share width + 2·clearance − d of y in every band. Under
    // 2·clearance that is less than any other axis's overlap (every box is at least 2·clearance
    // thick), and no pair of pieces overlaps more on y, which all their boxes have as an axis:
    // D_c = bands × (width + 2·clearance − d), and 0 from d = width + 2·clearance on.
    MotionMechanism a = testing::sample_mechanism(MotionKind::horizontal);
    const double width = a.horizontal().width;
    const VolumeOptions options;
    const CollisionVolume va = collision_volume(a, options);
    double previous = std::numeric_limits<double>::infinity();
    for (double d : {width + 0.05, width + 0.3, width + 0.6, width + 0.95}) {
        MotionMechanism b = a;
        b.horizontal().offset += d;
        const double depth = collision_depth(va, collision_volume(b, options));
        EXPECT_NEAR(depth, options.bands * (width + 2 * options.clearance - d), 1e-9) << d;
        EXPECT_LT(depth, previous);
        previous = depth;
    }
    MotionMechanism b = a;
    b.horizontal().offset += width + 2 * options.clearance + 1e-6;
    EXPECT_EQ(collision_depth(va, collision_volume(b, options)), 0.0);
}

TEST(CollisionVolume, CollideAnswersWhetherTheDepthIsPositive)
{
    // collide stops at the first two pieces that share room; it must say yes exactly when
    // collision_depth is positive. Every kind against every kind, the second moved along the fold
    // and across it by a grid of offsets: both answers occur, and they always agree.
    const VolumeOptions options;
    int yes = 0, no = 0;
    for (int ka = 0; ka < motion_kind_count; ++ka)
        for (int kb = 0; kb < motion_kind_count; ++kb) {
            const MotionMechanism a = testing::sample_mechanism(MotionKind(ka));
            const CollisionVolume va = collision_volume(a, options);
            for (double dy = -60; dy <= 60; dy += 7.5) {
                MotionMechanism b = testing::sample_mechanism(MotionKind(kb));
                fold_offset(b) += dy;
                const CollisionVolume vb = collision_volume(b, options);
                const bool depth = collision_depth(va, vb) > 0;
                EXPECT_EQ(collide(va, vb), depth) << ka << " " << kb << " dy " << dy;
                EXPECT_EQ(collide(vb, va), depth) << kb << " " << ka << " dy " << dy;
                (depth ? yes : no) += 1;
            }
        }
    EXPECT_GT(yes, 50);
    EXPECT_GT(no, 50);
}

// Points spread over a posed patch: its outline's vertices and a grid over each triangle of its
// fan (the patches are convex), so a point of any of the patch's pieces is among them.
std::vector<Vec3> points_over(const std::vector<Vec3>& outline)
{
    std::vector<Vec3> points = outline;
    constexpr int n = 8;
    for (std::size_t t = 1; t + 1 < outline.size(); ++t)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j)
                points.push_back(outline[0] + (outline[t] - outline[0]) * i / double(n) +
                                 (outline[t + 1] - outline[0]) * j / double(n));
    return points;
}

TEST(CollisionVolume, HoldsEverySimulatedPatchOver91Angles)
{
    // Every point of every patch, posed by the simulator at 91 angles (x divided by sin(θ/2), the
    // volume's frame), lies in the box of one piece of its band whose side admits it (side s:
    // s·x >= 0): the volume and its sides hold the paper the generators build.
    std::vector<double> angles;
    for (int k = 0; k <= 90; ++k)
        angles.push_back(M_PI * k / 90);
    const VolumeOptions options;
    for (const auto& [kind, m] : samples()) {
        const CollisionVolume volume = collision_volume(m, options);
        ASSERT_EQ(int(volume.bands.size()), options.bands);
        const std::size_t pieces = volume.sides.size();
        ASSERT_EQ(volume.aligned.size(), pieces * options.bands);
        const Built b = build(m);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete);
        int outside = 0, checked = 0;
        for (const FoldState& state : sweep.value.states) {
            if (state.angle == 0.0)
                continue; // flat: the volume's frame, x / sin(θ/2), is a limit there
            const int band = std::min(options.bands - 1, int(state.angle / (M_PI / options.bands)));
            const double across = 1.0 / std::sin(state.angle / 2);
            for (int id : b.patches) {
                const Patch* patch = b.scaffold.find_patch(id);
                for (const Vec3& x :
                     points_over(posed_outline(*patch, state.poses[b.scaffold.patch_index(id)]))) {
                    ++checked;
                    const Vec3 mapped(x.x() * across, x.y(), x.z());
                    bool held = false;
                    for (std::size_t i = 0; i < pieces && !held; ++i) {
                        const OrientedBox& box = volume.aligned[band * pieces + i];
                        held = volume.sides[i] * x.x() >= -1e-9 &&
                               ((mapped - box.centre).cwiseAbs() - box.half).maxCoeff() <= 1e-9;
                    }
                    if (!held)
                        ++outside;
                }
            }
        }
        EXPECT_GT(checked, 91 * 3);
        EXPECT_EQ(outside, 0) << kind;
    }
}

} // namespace
} // namespace popup::motion
