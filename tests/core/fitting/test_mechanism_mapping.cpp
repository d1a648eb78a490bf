// Table 5.1: which mechanism each prism becomes. With samples, by their distance to each
// mechanism's patches (docs/MATH.md, "Mapping by distance"), worked out by hand from the prism's
// dimensions; without, or on a tie, by eq. 5.1, whose areas are worked out by hand too
// (docs/DESIGN.md, "Mapping by distance (why eq. 5.1 never picked a v-fold)").
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/fitting/mechanism_patches.hpp"

namespace popup {
namespace {

RansacResult one_prism_on_the_card(const Prism& prism)
{
    RansacResult fit;
    PrismHost card;
    card.name = "central fold";
    card.length = 200.0;
    card.across_min = -100.0;
    card.across_max = 100.0;
    fit.hosts.push_back(card);
    fit.prisms.push_back(prism);
    return fit;
}

Prism triangular(double length, double s0, double s1, double apex_s, double height)
{
    Prism p;
    p.kind = Prism::Kind::triangular;
    p.a0 = 10.0;
    p.a1 = 10.0 + length;
    p.s0 = s0;
    p.s1 = s1;
    p.apex_s = apex_s;
    p.height = height;
    return p;
}

/// The prism of the tests below: a in [10, 50] (a' = a − 10 in [0, 40]), feet at s = ±20, apex
/// 30 up over the fold. As a v-fold (plan_v_fold): O (0, 10, 0), A (20, 50, 0), B (−20, 50, 0),
/// P (0, 50, 30), its wings O-A-P and O-P-B; the card's frame is the host's, (s, a, t) = (x, y, z).
Prism spine_prism(Prism::Kind kind)
{
    Prism p = triangular(40.0, -20.0, 20.0, 0.0, 30.0);
    p.kind = kind;
    return p;
}

/// `points` as the samples the search assigned to prism `k` of `fit` (the mapping reads no
/// normal).
SurfaceSamples owned_by(RansacResult& fit, const std::vector<Vec3>& points, int k = 0)
{
    SurfaceSamples samples;
    samples.points = points;
    samples.normals.assign(points.size(), Vec3::UnitZ());
    fit.owner.assign(points.size(), k);
    return samples;
}

/// Sum of the distances from `points` to the patches of `kind` planned for `prism` on the card.
double distance_sum(MechanismKind kind, const Prism& prism, const std::vector<Vec3>& points)
{
    // A copy: a reference into the returned temporary dangled (GCC 14 found it).
    const PrismHost card = one_prism_on_the_card(prism).hosts[0];
    const std::vector<HostPolygon> patches =
        design_patches(plan_mechanism(kind, prism, card), card);
    double sum = 0;
    for (const Vec3& p : points)
        sum += distance_to_patches(p, patches);
    return sum;
}

// The v-fold wing O-A-P's plane: normal OP × OA = (0, 40, 30) × (20, 40, 0) = (−1200, 600, −800).
const double wing_normal = std::sqrt(1200.0 * 1200.0 + 600.0 * 600.0 + 800.0 * 800.0);

TEST(FitMechanismMapping, WithoutSamplesAVFoldShapedPrismBecomesATentByEq51)
{
    // A v-fold's shape as a prism: two slopes meeting on a spine 30 mm up, 20 mm either side of
    // the fold, 40 mm along it. Faces: bottom 40·40 = 1600, slopes 2·40·√(20²+30²) = 2884.44,
    // ends 2·(40·30/2) = 1200; total 5684.44. A tent covers both slopes: e = 1 − 2884.44/5684.44
    // = 0.49258. A v-fold's wings stand on the diagonals and cover half of them: e = 0.74629.
    const Prism spine = triangular(40.0, -20.0, 20.0, 0.0, 30.0);
    const double slopes = 2 * 40.0 * std::sqrt(20.0 * 20.0 + 30.0 * 30.0);
    const double total = 1600.0 + slopes + 1200.0;
    const Mapping mapped = map_mechanisms(one_prism_on_the_card(spine), SurfaceSamples{});
    ASSERT_EQ(mapped.plans.size(), 1u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "tent_fold");
    EXPECT_NEAR(mapped.coverage_error, 0.49258, 1e-5);
    EXPECT_NEAR(mapped.coverage_error, 1.0 - slopes / total, 1e-12);

    const MechanismPlan v =
        plan_mechanism(MechanismKind::v_fold, spine, one_prism_on_the_card(spine).hosts[0]);
    EXPECT_NEAR(v.coverage_error(), 0.74629, 1e-5);
    // Its spine runs from O over the prism's far end: √(40² + 30²) = 50 mm at atan(30/40).
    EXPECT_NEAR(v.parameter_values().at("spine"), 50.0, 1e-12);
    EXPECT_NEAR(v.parameter_values().at("spine_angle"), std::atan2(30.0, 40.0), 1e-12);
}

TEST(FitMechanismMapping, WithoutSamplesNoProportionOfPrismMakesTheVFoldWin)
{
    // The v-fold covers half of what the tent (triangular) covers, and w·h of the box's
    // w·across + 2wh + 2·across·h (rectangular): whatever the proportions, it loses by
    // half the slopes (or the box's top, ends and one side) over the same face total.
    for (double length : {2.0, 40.0, 180.0})
        for (double half : {3.0, 20.0, 90.0})
            for (double height : {1.0, 30.0, 150.0}) {
                const Prism tri = triangular(length, -half, half, 0.0, height);
                const Mapping mapped = map_mechanisms(one_prism_on_the_card(tri), SurfaceSamples{});
                ASSERT_EQ(mapped.plans.size(), 1u);
                EXPECT_EQ(mapped.plans[0].kind_name(), "tent_fold")
                    << length << " " << half << " " << height;
                const double slopes = 2 * length * std::hypot(half, height);
                const double total = length * 2 * half + slopes + 2 * half * height;
                const MechanismPlan v =
                    plan_mechanism(MechanismKind::v_fold, tri, one_prism_on_the_card(tri).hosts[0]);
                EXPECT_NEAR(v.coverage_error() - mapped.coverage_error, 0.5 * slopes / total,
                            1e-12);

                Prism box = tri;
                box.kind = Prism::Kind::rectangular;
                const Mapping boxed = map_mechanisms(one_prism_on_the_card(box), SurfaceSamples{});
                ASSERT_EQ(boxed.plans.size(), 1u);
                EXPECT_EQ(boxed.plans[0].kind_name(), "box_fold");
                const double across = 2 * half;
                const double box_total =
                    2 * length * across + 2 * length * height + 2 * across * height;
                EXPECT_NEAR(boxed.coverage_error, length * across / box_total, 1e-12);
                const MechanismPlan vb =
                    plan_mechanism(MechanismKind::v_fold, box, one_prism_on_the_card(box).hosts[0]);
                EXPECT_NEAR(vb.coverage_error(), 1.0 - length * height / box_total, 1e-12);
            }
}

TEST(FitMechanismMapping, SamplesOnBothSlopesMakeATent)
{
    // Four samples on the ridge (0, 10 + a', 30), a' = 0, 10, 20, 30, and six halfway up the
    // slopes (±10, 10 + a', 15), a' = 10, 20, 30: all on the tent's slopes, distance 0. From the
    // v-fold: a ridge sample lies beside both wings, nearest to the spine OP, the line
    // t = 30a'/40 in the plane s = 0, at 30·(40 − a')/50 = 24, 18, 12, 6 mm. A slope sample
    // (10, a, 15) lies over the wing O-A-P, (−1200·10 + 600a' − 800·15)/|n| = 600(a' − 40)/|n|
    // from its plane: 11.523, 7.682, 3.841 mm (its mirror as far from O-P-B). Mean 10.609 mm.
    const Prism tri = spine_prism(Prism::Kind::triangular);
    std::vector<Vec3> points;
    double v_fold_sum = 0;
    for (double a : {0.0, 10.0, 20.0, 30.0}) {
        points.push_back({0, 10 + a, 30});
        v_fold_sum += 0.6 * (40 - a);
    }
    for (double a : {10.0, 20.0, 30.0})
        for (double s : {-10.0, 10.0}) {
            points.push_back({s, 10 + a, 15});
            v_fold_sum += 600 * (40 - a) / wing_normal;
        }
    EXPECT_NEAR(v_fold_sum / 10, 10.609, 1e-3);
    EXPECT_NEAR(distance_sum(MechanismKind::v_fold, tri, points), v_fold_sum, 1e-9);
    EXPECT_NEAR(distance_sum(MechanismKind::tent_fold, tri, points), 0.0, 1e-9);

    RansacResult fit = one_prism_on_the_card(tri);
    const Mapping mapped = map_mechanisms(fit, owned_by(fit, points));
    ASSERT_EQ(mapped.plans.size(), 1u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "tent_fold");
    EXPECT_EQ(mapped.plans[0].samples, 10);
    EXPECT_NEAR(mapped.sample_distance, 0.0, 1e-9);
    EXPECT_NEAR(mapped.coverage_error, 0.49258, 1e-5); // eq. 5.1 still reported
}

TEST(FitMechanismMapping, SamplesOnAVFoldsWingsMakeAVFold)
{
    // Samples O + α·OP + β·OA = (20β, 10 + 40(α + β), 30α) on the ground wing and their mirrors
    // on the backdrop wing, α, β in {0.2, 0.4}: on the v-fold, distance 0. The tent's ground slope
    // is the line 30s + 20t = 600 in the section, so (20β, 30α) lies 600(1 − α − β)/√1300 from
    // it, over the slope: 9.985, 6.656, 6.656, 3.328 mm, mean 6.656 mm. By eq. 5.1 alone the
    // tent would win (0.49258 against 0.74629, the first test).
    const Prism tri = spine_prism(Prism::Kind::triangular);
    std::vector<Vec3> points;
    double tent_sum = 0;
    for (double alpha : {0.2, 0.4})
        for (double beta : {0.2, 0.4})
            for (double side : {-1.0, 1.0}) {
                points.push_back({side * 20 * beta, 10 + 40 * (alpha + beta), 30 * alpha});
                tent_sum += 600 * (1 - alpha - beta) / std::sqrt(1300.0);
            }
    EXPECT_NEAR(tent_sum / 8, 6.656, 1e-3);
    EXPECT_NEAR(distance_sum(MechanismKind::tent_fold, tri, points), tent_sum, 1e-9);
    EXPECT_NEAR(distance_sum(MechanismKind::v_fold, tri, points), 0.0, 1e-9);

    RansacResult fit = one_prism_on_the_card(tri);
    const Mapping mapped = map_mechanisms(fit, owned_by(fit, points));
    ASSERT_EQ(mapped.plans.size(), 1u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "v_fold");
    EXPECT_EQ(mapped.plans[0].name, "V1");
    EXPECT_NEAR(mapped.sample_distance, 0.0, 1e-9);
    EXPECT_NEAR(mapped.coverage_error, 0.74629, 1e-5);
}

TEST(FitMechanismMapping, SamplesOnABoxMakeABoxFold)
{
    // The rectangular prism s in [−20, 20], t in [0, 30], a in [10, 50]. Samples on its top over
    // the fold (0, 10 + a', 30), a' = 0, 10, 20, 30, and on its ground side (20, 10 + a', t),
    // a' = 10, 20, 30, t = 10, 20: on the box, distance 0. From the v-fold (the same wings: its
    // depth is min(s1, −s0) = 20): the top's 0.6·(40 − a') from the spine as for the tent's ridge,
    // the side's |−1200·20 + 600a' − 800t|/|n| from the wing O-A-P's plane, over the wing.
    const Prism box = spine_prism(Prism::Kind::rectangular);
    std::vector<Vec3> points;
    double v_fold_sum = 0;
    for (double a : {0.0, 10.0, 20.0, 30.0}) {
        points.push_back({0, 10 + a, 30});
        v_fold_sum += 0.6 * (40 - a);
    }
    for (double a : {10.0, 20.0, 30.0})
        for (double t : {10.0, 20.0}) {
            points.push_back({20, 10 + a, t});
            v_fold_sum += std::abs(-1200 * 20 + 600 * a - 800 * t) / wing_normal;
        }
    EXPECT_NEAR(distance_sum(MechanismKind::v_fold, box, points), v_fold_sum, 1e-9);
    EXPECT_NEAR(distance_sum(MechanismKind::box_fold, box, points), 0.0, 1e-9);

    RansacResult fit = one_prism_on_the_card(box);
    const Mapping mapped = map_mechanisms(fit, owned_by(fit, points));
    ASSERT_EQ(mapped.plans.size(), 1u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "box_fold");
    EXPECT_NEAR(mapped.sample_distance, 0.0, 1e-9);
    EXPECT_NEAR(mapped.coverage_error, 1600.0 / 8000.0, 1e-12); // the bottom, of 2·1600 + 4·1200
}

TEST(FitMechanismMapping, EqualDistancesGoToTheLowerCoverageError)
{
    // Samples on the far end's slope edges (s, 50, 30(1 − |s|/20)) lie on both the tent's slopes
    // and the v-fold's edges PA and PB: distance 0 either way, so eq. 5.1 decides (tent).
    const Prism tri = spine_prism(Prism::Kind::triangular);
    std::vector<Vec3> points;
    for (double s : {-15.0, -5.0, 5.0, 15.0})
        points.push_back({s, 50, 30 * (1 - std::abs(s) / 20)});
    EXPECT_NEAR(distance_sum(MechanismKind::v_fold, tri, points), 0.0, 1e-9);
    RansacResult fit = one_prism_on_the_card(tri);
    const Mapping mapped = map_mechanisms(fit, owned_by(fit, points));
    ASSERT_EQ(mapped.plans.size(), 1u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "tent_fold");
    EXPECT_NEAR(mapped.coverage_error, 0.49258, 1e-5);
}

TEST(FitMechanismMapping, APrismOnATopKeepsItsHostABoxFoldWhateverTheSamples)
{
    // The rectangular prism's samples on the v-fold's wings (as above, α, β in {0.2, 0.4}, ground
    // side): a v-fold's. The box's nearest walls are C at 20β and, for the last, the back end at
    // 40(1 − α − β): 4, 8, 4, 8 mm, mean 6 mm. Alone it becomes the v-fold; with a prism on its
    // top it must stay a box fold (only a box offers a top).
    const Prism box = spine_prism(Prism::Kind::rectangular);
    std::vector<Vec3> points;
    for (double alpha : {0.2, 0.4})
        for (double beta : {0.2, 0.4})
            points.push_back({20 * beta, 10 + 40 * (alpha + beta), 30 * alpha});
    EXPECT_NEAR(distance_sum(MechanismKind::box_fold, box, points), 24.0, 1e-9);

    RansacResult alone = one_prism_on_the_card(box);
    const Mapping single = map_mechanisms(alone, owned_by(alone, points));
    ASSERT_EQ(single.plans.size(), 1u);
    EXPECT_EQ(single.plans[0].kind_name(), "v_fold");

    RansacResult fit = one_prism_on_the_card(box);
    PrismHost top;
    top.name = "P1.top";
    top.parent = 0;
    top.part = "top";
    top.origin = Vec3(0, 10, 30);
    top.length = 40.0;
    top.across_min = -20.0;
    top.across_max = 20.0;
    fit.hosts.push_back(top);
    Prism tower;
    tower.host = 1;
    tower.a0 = 5.0;
    tower.a1 = 25.0;
    tower.s0 = -10.0;
    tower.s1 = 10.0;
    tower.height = 10.0;
    fit.prisms.push_back(tower);
    const Mapping mapped = map_mechanisms(fit, owned_by(fit, points));
    ASSERT_EQ(mapped.plans.size(), 2u);
    EXPECT_EQ(mapped.plans[0].kind_name(), "box_fold");
    EXPECT_EQ(mapped.plans[1].kind_name(), "box_fold"); // no samples: eq. 5.1
    EXPECT_EQ(mapped.plans[1].host, "B1.top");
    EXPECT_NEAR(mapped.sample_distance, 6.0, 1e-9);
    EXPECT_NEAR(mapped.plans[0].sample_distance, 6.0, 1e-9);
    EXPECT_EQ(mapped.plans[1].samples, 0);
}

TEST(FitMechanismMapping, OwnersMustMatchTheSamples)
{
    RansacResult fit = one_prism_on_the_card(spine_prism(Prism::Kind::triangular));
    SurfaceSamples samples = owned_by(fit, {Vec3(0, 20, 30), Vec3(0, 30, 30)});
    fit.owner.pop_back();
    EXPECT_THROW(map_mechanisms(fit, samples), std::invalid_argument);
    fit.owner = {0, 1}; // only prism 0 exists
    try {
        map_mechanisms(fit, samples);
        FAIL() << "owner 1 of one prism was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("fit.owner[1] = 1, must be -1 or in [0, 0]"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace popup
