// Table 5.1 under eq. 5.1: which mechanism each prism becomes. The areas are worked out by hand
// from the prism's dimensions (docs/DESIGN.md, "Why eq. 5.1 never picks a v-fold").
#include <gtest/gtest.h>

#include <cmath>

#include "popup/fitting/mechanism_mapping.hpp"

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

TEST(FitMechanismMapping, AVFoldShapedPrismBecomesATentBecauseItsWingsCoverHalfTheSlopes)
{
    // A v-fold's shape as a prism: two slopes meeting on a spine 30 mm up, 20 mm either side of
    // the fold, 40 mm along it. Faces: bottom 40·40 = 1600, slopes 2·40·√(20²+30²) = 2884.44,
    // ends 2·(40·30/2) = 1200; total 5684.44. A tent covers both slopes: e = 1 − 2884.44/5684.44
    // = 0.49258. A v-fold's wings stand on the diagonals and cover half of them: e = 0.74629.
    const Prism spine = triangular(40.0, -20.0, 20.0, 0.0, 30.0);
    const double slopes = 2 * 40.0 * std::sqrt(20.0 * 20.0 + 30.0 * 30.0);
    const double total = 1600.0 + slopes + 1200.0;
    const Mapping mapped = map_mechanisms(one_prism_on_the_card(spine));
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

TEST(FitMechanismMapping, NoProportionOfPrismMakesTheVFoldWin)
{
    // The v-fold covers half of what the tent (triangular) covers, and w·h of the box's
    // w·across + 2wh + 2·across·h (rectangular): whatever the proportions, it loses by
    // half the slopes (or the box's top, ends and one side) over the same face total.
    for (double length : {2.0, 40.0, 180.0})
        for (double half : {3.0, 20.0, 90.0})
            for (double height : {1.0, 30.0, 150.0}) {
                const Prism tri = triangular(length, -half, half, 0.0, height);
                const Mapping mapped = map_mechanisms(one_prism_on_the_card(tri));
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
                const Mapping boxed = map_mechanisms(one_prism_on_the_card(box));
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

} // namespace
} // namespace popup
