// The mapping's closed forms of a mechanism's patches at the design state against what its
// generator builds on a card open flat (docs/MATH.md, "Mapping by distance").
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "popup/fitting/mechanism_mapping.hpp"
#include "popup/fitting/mechanism_patches.hpp"
#include "popup/model/card.hpp"

namespace popup {
namespace {

double polygon_area(const HostPolygon& p)
{
    Vec3 n = Vec3::Zero();
    for (size_t i = 0; i < p.size(); ++i)
        n += p[i].cross(p[(i + 1) % p.size()]);
    return 0.5 * n.norm();
}

/// Builds `plan` on a card's central fold (the card's frame is the host's: x across, y along
/// the fold, z up) and checks the closed forms cover the generated patches and nothing more.
void expect_same_paper(const MechanismPlan& plan)
{
    CardParams card;
    Scaffold s = make_card(card).value;
    const Result<MechanismParts> built = add_mechanism(s, central_fold(s), plan);
    ASSERT_TRUE(built.ok) << plan.kind_name() << ": " << built.diagnostics.at(0).message;
    PrismHost host;
    const std::vector<HostPolygon> closed = design_patches(plan, host);
    double generated_area = 0, closed_area = 0;
    std::vector<Patch> made;
    for (int id : built.value.patches) {
        Patch p = *s.find_patch(id);
        p.derive_frame();
        generated_area += p.area();
        for (const Vec3& v : p.outer)
            EXPECT_LT(distance_to_patches(v, closed), 1e-9) << plan.kind_name() << " " << p.name;
        made.push_back(p);
    }
    for (const HostPolygon& polygon : closed) {
        closed_area += polygon_area(polygon);
        for (const Vec3& v : polygon) {
            bool on_one = false;
            for (const Patch& p : made)
                on_one = on_one || p.contains(v, 1e-9);
            EXPECT_TRUE(on_one) << plan.kind_name() << ": (" << v.transpose() << ")";
        }
    }
    EXPECT_NEAR(generated_area, closed_area, 1e-6) << plan.kind_name();
}

Prism prism(Prism::Kind kind, double apex_s)
{
    Prism p;
    p.kind = kind;
    p.a0 = 20.0;
    p.a1 = 70.0;
    p.s0 = -25.0;
    p.s1 = 25.0;
    p.apex_s = apex_s;
    p.height = 35.0;
    return p;
}

TEST(FitMechanismPatches, ClosedFormsAreTheGeneratedPaperOnAFlatHost)
{
    const PrismHost card;
    expect_same_paper(
        plan_mechanism(MechanismKind::box_fold, prism(Prism::Kind::rectangular, 0.0), card));
    expect_same_paper(
        plan_mechanism(MechanismKind::v_fold, prism(Prism::Kind::rectangular, 0.0), card));
    expect_same_paper(
        plan_mechanism(MechanismKind::tent_fold, prism(Prism::Kind::triangular, 0.0), card));
    expect_same_paper(
        plan_mechanism(MechanismKind::v_fold, prism(Prism::Kind::triangular, 0.0), card));
    // An apex off the fold: the tent's backdrop slope is Foot + Slope − FootBackdrop, so the
    // generator's apex is not the prism's; the closed form follows the generator.
    const MechanismPlan leaning =
        plan_mechanism(MechanismKind::tent_fold, prism(Prism::Kind::triangular, 8.0), card);
    expect_same_paper(leaning);
    MechanismPlan trimmed =
        plan_mechanism(MechanismKind::box_fold, prism(Prism::Kind::rectangular, 0.0), card);
    trimmed.as<BoxFoldParams>().back = false;
    expect_same_paper(trimmed);
}

TEST(FitMechanismPatches, AStepStandsOutFromTheWallAtARightAngle)
{
    // On a box's side (across along the page, up the wall): run 12 out, 18 up, from a = 5 to 25.
    PrismHost side;
    side.flat = false;
    side.part = "side_ground";
    Prism step;
    step.a0 = 5;
    step.a1 = 25;
    step.s1 = 12;
    step.height = 18;
    const std::vector<HostPolygon> patches =
        design_patches(plan_mechanism(MechanismKind::step_fold, step, side), side);
    ASSERT_EQ(patches.size(), 2u);
    EXPECT_NEAR(distance_to_patches(Vec3(12, 10, 9), patches), 0.0, 1e-12);  // riser
    EXPECT_NEAR(distance_to_patches(Vec3(6, 10, 18), patches), 0.0, 1e-12);  // tread
    EXPECT_NEAR(distance_to_patches(Vec3(6, 10, 9), patches), 6.0, 1e-12);   // inside the corner
    EXPECT_NEAR(distance_to_patches(Vec3(12, 30, 18), patches), 5.0, 1e-12); // past the nose
    side.part = "side_backdrop"; // the runs swap, the shape stays
    EXPECT_NEAR(distance_to_patches(
                    Vec3(12, 10, 9),
                    design_patches(plan_mechanism(MechanismKind::step_fold, step, side), side)),
                0.0, 1e-12);
}

TEST(FitMechanismPatches, OnlyTheMappedKindsHavePatches)
{
    EXPECT_THROW(design_patches(DesignedMechanism::of_kind(MechanismKind::rotation_arm), {}),
                 std::invalid_argument);
    EXPECT_EQ(distance_to_patches(Vec3::Zero(), {}), 1e300);
}

} // namespace
} // namespace popup
