// Depth layers (thesis §5.1.3): a "stepped-front truck" built here, a cab box whose front carries
// a bonnet block standing 25 proud of it, so the cab's front faces sit at two known depths and
// the bonnet's front is a known polygon (a chamfered rectangle, area by hand). A load bed as deep
// behind the cab keeps the cab centred on the card's fold (a box fold is centred on its hinge).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fitting/synthetic_models.hpp"
#include "popup/fitting/fit_depth_layers.hpp"
#include "popup/fitting/fit_design.hpp"
#include "popup/fitting/fit_metrics.hpp"
#include "popup/simulation/check_validity.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

// Cab: x in [-20, 20] (x faces the viewer), y in [0, 60], z in [0, 40]. Bonnet: x in
// [20, 45], y in [10, 50], z in [0, 20], its two top edges along x chamfered 6 by 6. Load bed:
// x in [-45, -20], y in [5, 55], z in [0, 30]. Roof beacon: x in [-12, 12], y in [20, 40], z in
// [40, 52].
constexpr double kCabFront = 20, kBonnetFront = 45, kChamfer = 6;
constexpr double kBonnetArea = 40 * 20 - 2 * (kChamfer * kChamfer / 2); // 764

ModelMesh stepped_truck()
{
    const ModelMesh cab = box_mesh({-20, 0, 0}, {kCabFront, 60, 40});
    const std::vector<Vec2> front{{10, 0},
                                  {50, 0},
                                  {50, 20 - kChamfer},
                                  {50 - kChamfer, 20},
                                  {10 + kChamfer, 20},
                                  {10, 20 - kChamfer}};
    const double half = (kBonnetFront - kCabFront) / 2;
    const ModelMesh bonnet =
        moved(extrude_elevation(front, half), Mat3::Identity(), 1.0, Vec3(kCabFront + half, 0, 0));
    const ModelMesh bed = box_mesh({-45, 5, 0}, {-20, 55, 30});
    const ModelMesh beacon = box_mesh({-12, 20, 40}, {12, 40, 52});
    ModelMesh m = join({cab, bonnet, bed, beacon});
    m.source = "stepped truck";
    return m;
}

FitOptions truck_options()
{
    FitOptions o;
    o.up = Vec3::UnitZ();
    o.facing = Vec3::UnitX();
    // One primitive: the cab. Bonnet and bed are left to the depth layers of its front and back.
    o.max_mechanisms = 1;
    return o;
}

double scale_of(const FitResult& r)
{
    return r.model_to_card.block<3, 1>(0, 0).norm();
}

Vec3 to_card(const FitResult& r, const Vec3& x)
{
    return r.model_to_card.topLeftCorner<3, 3>() * x + r.model_to_card.topRightCorner<3, 1>();
}

double mean_distance(const ModelMesh& model, const FitResult& r)
{
    FitMetricsOptions mo;
    mo.samples = 20000;
    mo.seed = 5;
    const auto m = fit_metrics(model, r.model_to_card, r.scaffold, {}, mo);
    EXPECT_TRUE(m.ok);
    return m.value.model_to_popup_mm.mean;
}

std::string describe(const FitResult& r)
{
    std::string s;
    for (const auto& m : r.mechanisms)
        s += m.name + " " + m.kind_name() + " on " + m.host + "; ";
    for (const auto& x : r.repairs)
        s += x.mechanism + " " + x.action + ": " + x.reason + "; ";
    return s;
}

TEST(FitDepthLayers, SteppedTruckFrontGetsTheBonnetAsANestedStep)
{
    const ModelMesh model = stepped_truck();
    const auto fit = fit_design(model, truck_options());
    ASSERT_TRUE(fit.ok) << (fit.diagnostics.empty() ? "" : fit.diagnostics[0].message);
    const FitResult& r = fit.value;
    ASSERT_TRUE(r.valid) << describe(r);
    EXPECT_TRUE(check_validity(r.scaffold).valid());
    ASSERT_GE(r.mechanisms.size(), 2u) << describe(r);
    const FittedMechanism& cab = r.mechanisms[0];
    ASSERT_EQ(cab.kind_name(), "box_fold") << describe(r);
    const FittedMechanism* step = nullptr;
    for (const FittedMechanism& m : r.mechanisms)
        if (m.host == cab.name + ".side_ground" && m.kind_name() == "step_fold")
            step = &m;
    ASSERT_TRUE(step) << describe(r);
    const double s = scale_of(r);
    const double tol = 0.02 * (kBonnetFront + 20) * s; // 2 % of the bounding box along x
    // The step's riser stands where the bonnet's front is, 25 in front of the cab's.
    EXPECT_NEAR(step->parameter_values().at("run_ground"), (kBonnetFront - kCabFront) * s, tol);
    EXPECT_NEAR(step->parameter_values().at("run_backdrop"), 20 * s, 0.02 * 40 * s);
    EXPECT_NEAR(step->parameter_values().at("width"), 40 * s, 0.02 * 60 * s);
    const double bonnet_x = to_card(r, Vec3(kBonnetFront, 30, 10)).x();
    const Patch* riser = nullptr;
    for (const Patch& p : r.scaffold.patches)
        if (p.name == step->name + ".riser")
            riser = &p;
    ASSERT_TRUE(riser);
    for (const Vec3& x : riser->outer)
        EXPECT_NEAR(x.x(), bonnet_x, tol);
    // Its outline is the bonnet's front: the chamfered rectangle.
    const FittedProfile* profile = nullptr;
    for (const FittedProfile& p : r.profiles)
        if (p.mechanism == step->name && p.part == "riser")
            profile = &p;
    ASSERT_TRUE(profile) << describe(r);
    EXPECT_NEAR(profile->area, kBonnetArea * s * s, 0.02 * kBonnetArea * s * s);
    // The load bed behind: a step on the backdrop side pair, whose wall (R) is its ground.
    const FittedMechanism* bed = nullptr;
    for (const FittedMechanism& m : r.mechanisms)
        if (m.host == cab.name + ".side_backdrop" && m.kind_name() == "step_fold")
            bed = &m;
    ASSERT_TRUE(bed) << describe(r);
    EXPECT_NEAR(bed->parameter_values().at("run_backdrop"), 25 * s, tol);
    EXPECT_NEAR(bed->parameter_values().at("run_ground"), 30 * s, 0.02 * 52 * s);
    EXPECT_NEAR(bed->parameter_values().at("width"), 50 * s, 0.02 * 60 * s);
    // The beacon on the roof: a box fold on the cab's top, as high as the beacon.
    const FittedMechanism* beacon = nullptr;
    for (const FittedMechanism& m : r.mechanisms)
        if (m.host == cab.name + ".top" && m.kind_name() == "box_fold")
            beacon = &m;
    ASSERT_TRUE(beacon) << describe(r);
    EXPECT_NEAR(beacon->parameter_values().at("height"), 12 * s, 0.02 * 52 * s);
    EXPECT_NEAR(beacon->parameter_values().at("depth_ground"), 12 * s, tol);
    EXPECT_NEAR(beacon->parameter_values().at("depth_backdrop"), 12 * s, tol);
    EXPECT_NEAR(beacon->parameter_values().at("width"), 20 * s, 0.02 * 60 * s);
    // Reported as kept, each with the distances that justified it.
    std::map<std::string, std::string> kept; // face -> mechanism
    for (const FittedDepthLayer& l : r.depth_layers)
        if (l.kept) {
            EXPECT_EQ(l.box, cab.name);
            kept[l.face] = l.mechanism;
            EXPECT_LT(l.mean_after_mm, l.mean_before_mm);
        }
    EXPECT_EQ(kept, (std::map<std::string, std::string>{
                        {"front", step->name}, {"back", bed->name}, {"top", beacon->name}}))
        << describe(r);
    EXPECT_EQ(r.mechanisms.size(), 4u) << describe(r);
    // The model is closer to the pop-up than without depth layers (measured independently of
    // the stage's own comparison: other samples, other seed).
    FitOptions off = truck_options();
    off.depth_layers = false;
    const auto flat = fit_design(model, off);
    ASSERT_TRUE(flat.ok && flat.value.valid);
    EXPECT_EQ(flat.value.mechanisms.size(), 1u);
    EXPECT_TRUE(flat.value.depth_layers.empty());
    const double with = mean_distance(model, r), without = mean_distance(model, flat.value);
    EXPECT_LT(with, without);
    // Bonnet, bed and beacon faces were up to 25 from the paper; now they are on it.
    EXPECT_LT(with, 0.5 * without);
}

TEST(FitDepthLayers, PlainCuboidHasNoDepthLayer)
{
    const auto fit = fit_design(cuboid_model(), FitOptions());
    ASSERT_TRUE(fit.ok && fit.value.valid);
    EXPECT_EQ(fit.value.mechanisms.size(), 1u) << describe(fit.value);
    for (const FittedDepthLayer& l : fit.value.depth_layers)
        EXPECT_FALSE(l.kept) << l.reason;
    for (const FitRepair& x : fit.value.repairs)
        EXPECT_NE(x.action, "layer kept") << x.reason;
}

} // namespace

namespace {

TEST(FitDepthLayers, WhatThePrimitivesAlreadyModelIsNotLayeredAgain)
{
    // With room for more primitives, RANSAC finds bonnet, bed and beacon itself (steps on the
    // cab's sides, a box on its top); their layers stand where those are and are dropped.
    FitOptions o = truck_options();
    o.max_mechanisms = 8;
    const auto fit = fit_design(stepped_truck(), o);
    ASSERT_TRUE(fit.ok && fit.value.valid);
    const FitResult& r = fit.value;
    EXPECT_EQ(r.mechanisms.size(), 4u) << describe(r);
    for (const FittedMechanism& m : r.mechanisms)
        EXPECT_EQ(m.primitive.find("depth layer"), std::string::npos) << m.name;
    ASSERT_EQ(r.depth_layers.size(), 3u) << describe(r);
    for (const FittedDepthLayer& l : r.depth_layers) {
        EXPECT_FALSE(l.kept);
        EXPECT_NE(l.reason.find("already carries"), std::string::npos) << l.reason;
    }
}

TEST(FitDepthLayers, ALayerThinnerThanTheNarrowestGluedPartIsDroppedAndSaysSo)
{
    // A plate 4 proud of the cab's front (and one on its back, to keep the cab centred): about
    // 6 mm on the card, below min_part_mm (11.1 mm).
    ModelMesh m = join({box_mesh({-20, 0, 0}, {20, 60, 40}), box_mesh({20, 20, 0}, {24, 40, 25}),
                        box_mesh({-24, 20, 0}, {-20, 40, 25})});
    const auto fit = fit_design(m, truck_options());
    ASSERT_TRUE(fit.ok && fit.value.valid);
    const FitResult& r = fit.value;
    const double s = scale_of(r);
    ASSERT_LT(4 * s, FitOptions().min_part_mm);
    EXPECT_EQ(r.mechanisms.size(), 1u) << describe(r);
    ASSERT_EQ(r.depth_layers.size(), 2u) << describe(r);
    for (const FittedDepthLayer& l : r.depth_layers) {
        EXPECT_FALSE(l.kept);
        EXPECT_NEAR(l.depth, 4 * s, 0.02 * 48 * s);
        EXPECT_NE(l.reason.find("below min_part_mm"), std::string::npos) << l.reason;
    }
    // With no narrowest part, the same plaques are kept.
    FitOptions any = truck_options();
    any.min_part_mm = 0;
    const auto thin = fit_design(m, any);
    ASSERT_TRUE(thin.ok && thin.value.valid);
    EXPECT_EQ(thin.value.mechanisms.size(), 3u) << describe(thin.value);
}

} // namespace

namespace {

TEST(FitDepthLayers, BadOptionsAreNamedWithTheirRange)
{
    DepthLayerFitOptions o;
    o.min_part_mm = -1;
    o.metric_samples = 5;
    const auto r =
        fit_depth_layers(cuboid_model(), Eigen::Matrix4d::Identity(), Scaffold(), {}, {}, o);
    ASSERT_FALSE(r.ok);
    ASSERT_EQ(r.diagnostics.size(), 2u);
    EXPECT_EQ(r.diagnostics[0].code, DiagnosticCode::bad_option);
    EXPECT_NE(r.diagnostics[0].message.find("min_part_mm = -1, must be a length >= 0 mm"),
              std::string::npos)
        << r.diagnostics[0].message;
    EXPECT_NE(r.diagnostics[1].message.find("metric_samples = 5, must be 100 to 10000000"),
              std::string::npos)
        << r.diagnostics[1].message;
}

} // namespace
