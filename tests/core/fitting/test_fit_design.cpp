#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fitting/synthetic_models.hpp"
#include "popup/fitting/fit_design.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "popup/simulation/check_validity.hpp"

using namespace popup;
using namespace popup::testing;

namespace {

/// The scale fit_design must use (docs/MATH.md, Fitting): closed, a box fold reaches its height
/// plus its half depth from the fold, and its end panels stand out of its ends by its half depth:
/// the length plus the depth fits the card's usable width, height plus half depth a page's.
double expected_scale(double length, double half_depth, double height, const FitOptions& o)
{
    return std::min(o.card.width * (1 - 2 * o.margin) / (length + 2 * half_depth),
                    o.card.depth * (1 - 2 * o.margin) / (height + half_depth));
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
        if (m.kind_name() == type && nth-- == 0)
            return &m;
    return nullptr;
}

std::string describe(const FitResult& r)
{
    std::string s;
    for (const auto& m : r.mechanisms) {
        s += m.name + " " + m.kind_name() + " on " + m.host + ":";
        for (const auto& [k, v] : m.parameter_values())
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
    EXPECT_EQ(box.kind_name(), "box_fold");
    EXPECT_EQ(box.host, "central fold");
    EXPECT_TRUE(r.valid);
    EXPECT_TRUE(check_validity(r.scaffold).valid());

    // 40 x 120 x 30: the fold runs along the 120, x is the 40 across it.
    const double s = expected_scale(120, 20, 30, o);
    const double length = 120 * s, depth = 20 * s, height = 30 * s;
    const auto& q = box.parameter_values();
    EXPECT_NEAR(q.at("width"), length, 0.02 * length);
    EXPECT_NEAR(q.at("depth_ground"), depth, 0.02 * 2 * depth);
    EXPECT_NEAR(q.at("depth_backdrop"), depth, 0.02 * 2 * depth);
    EXPECT_NEAR(q.at("height"), height, 0.02 * height);
    EXPECT_NEAR(q.at("offset"), (o.card.width - length) / 2, 0.02 * length);

    // The design state is the cuboid: its surface lies on the patches.
    const Vec3 lo(-depth, (o.card.width - length) / 2, 0), hi(depth, lo.y() + length, height);
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
    const auto& q = tent->parameter_values();
    EXPECT_NEAR(q.at("width"), 110 * s, 0.02 * 110 * s);
    EXPECT_NEAR(q.at("foot"), 30 * s, 0.02 * 60 * s);
    EXPECT_NEAR(q.at("foot_backdrop"), 30 * s, 0.02 * 60 * s);
    EXPECT_NEAR(q.at("slope"), std::hypot(30, 36) * s, 0.02 * 36 * s);
}

/// Expected dimensions of a model of bounding box length x half depth x height, in card mm,
/// and the 2 % tolerance of each along its own axis.
struct Frame {
    double s, length, depth, height;
    Frame(double l, double half, double h, const FitOptions& o)
        : s(expected_scale(l, half, h, o)), length(l * s), depth(2 * half * s), height(h * s)
    {
    }
    double along(double model) const { return model * s; }
};

#define EXPECT_ALONG(value, model, frame) EXPECT_NEAR(value, (model)*frame.s, 0.02 * frame.length)
#define EXPECT_ACROSS(value, model, frame) EXPECT_NEAR(value, (model)*frame.s, 0.02 * frame.depth)
#define EXPECT_UP(value, model, frame) EXPECT_NEAR(value, (model)*frame.s, 0.02 * frame.height)

FitResult fitted(const ModelMesh& m, const FitOptions& o = FitOptions())
{
    auto r = fit_design(m, o);
    EXPECT_TRUE(r.ok) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
    EXPECT_TRUE(r.value.valid);
    if (!r.value.scaffold.patches.empty()) {
        EXPECT_TRUE(check_validity(r.value.scaffold).valid());
    }
    return r.value;
}

TEST(FitDesign, HouseIsABoxWithATentOnItsTop)
{
    const FitOptions o;
    const FitResult r = fitted(house_model(), o);
    ASSERT_EQ(r.mechanisms.size(), 2u) << describe(r);
    const Frame f(100, 30, 42, o);
    const FittedMechanism* box = find_type(r, "box_fold");
    const FittedMechanism* roof = find_type(r, "tent_fold");
    ASSERT_TRUE(box && roof) << describe(r);
    EXPECT_EQ(box->host, "central fold");
    EXPECT_EQ(roof->host, box->name + ".top");
    EXPECT_ALONG(box->parameter_values().at("width"), 100, f);
    EXPECT_ACROSS(box->parameter_values().at("depth_ground"), 30, f);
    EXPECT_UP(box->parameter_values().at("height"), 24, f);
    EXPECT_ALONG(roof->parameter_values().at("width"), 100, f);
    EXPECT_ACROSS(roof->parameter_values().at("foot"), 30, f);
    EXPECT_ACROSS(roof->parameter_values().at("foot_backdrop"), 30, f);
    EXPECT_UP(roof->parameter_values().at("slope"), std::hypot(30, 18), f);
}

TEST(FitDesign, TruckIsAStackOfBoxFolds)
{
    const FitOptions o;
    const FitResult r = fitted(truck_model(), o);
    ASSERT_EQ(r.mechanisms.size(), 3u) << describe(r);
    const Frame f(140, 20, 50, o);
    for (const auto& m : r.mechanisms)
        EXPECT_EQ(m.kind_name(), "box_fold") << describe(r);
    const auto& chassis = r.mechanisms[0].parameter_values();
    EXPECT_EQ(r.mechanisms[0].host, "central fold");
    EXPECT_ALONG(chassis.at("width"), 140, f);
    EXPECT_UP(chassis.at("height"), 14, f);
    EXPECT_ACROSS(chassis.at("depth_ground"), 20, f);
    // Cargo (y 0..80, 36 high) and cab (y 96..132, 24 high) on the chassis's top.
    const FittedMechanism* cargo = &r.mechanisms[1];
    const FittedMechanism* cab = &r.mechanisms[2];
    if (cargo->parameter_values().at("offset") > cab->parameter_values().at("offset"))
        std::swap(cargo, cab);
    EXPECT_EQ(cargo->host, r.mechanisms[0].name + ".top");
    EXPECT_EQ(cab->host, r.mechanisms[0].name + ".top");
    EXPECT_ALONG(cargo->parameter_values().at("offset"), 0, f);
    EXPECT_ALONG(cargo->parameter_values().at("width"), 80, f);
    EXPECT_UP(cargo->parameter_values().at("height"), 36, f);
    EXPECT_ALONG(cab->parameter_values().at("offset"), 96, f);
    EXPECT_ALONG(cab->parameter_values().at("width"), 36, f);
    EXPECT_UP(cab->parameter_values().at("height"), 24, f);
    // §4.2.2: closed, each box's end creases stand out by its half depth (20): the 16 between
    // cargo and cab is too little for both, so the panels facing each other come off.
    EXPECT_EQ(cargo->parameter_values().at("back"), 0.0);
    EXPECT_EQ(cargo->parameter_values().at("front"), 1.0);
    EXPECT_EQ(cab->parameter_values().at("front"), 0.0);
    EXPECT_EQ(cab->parameter_values().at("back"), 1.0);
    int trimmed = 0;
    for (const FitRepair& repair : r.repairs)
        trimmed += repair.action == "trimmed" &&
                   (repair.mechanism == cargo->name || repair.mechanism == cab->name);
    EXPECT_EQ(trimmed, 2);
}

TEST(FitDesign, LBuildingIsAWingBoxCarryingTheTower)
{
    const FitOptions o;
    const FitResult r = fitted(l_building_model(), o);
    ASSERT_EQ(r.mechanisms.size(), 2u) << describe(r);
    const Frame f(100, 20, 60, o);
    EXPECT_EQ(r.mechanisms[0].kind_name(), "box_fold");
    EXPECT_EQ(r.mechanisms[1].kind_name(), "box_fold");
    EXPECT_EQ(r.mechanisms[1].host, r.mechanisms[0].name + ".top");
    const auto& wing = r.mechanisms[0].parameter_values();
    const auto& tower = r.mechanisms[1].parameter_values();
    EXPECT_ALONG(wing.at("width"), 100, f);
    EXPECT_UP(wing.at("height"), 24, f);
    EXPECT_ACROSS(wing.at("depth_ground"), 20, f);
    EXPECT_ALONG(tower.at("width"), 30, f);
    EXPECT_UP(tower.at("height"), 36, f);
    // The tower stands at one end of the wing (which end is the card's y = 0 is the skew's).
    const double end =
        std::min(tower.at("offset"), wing.at("width") - tower.at("offset") - tower.at("width"));
    EXPECT_NEAR(end, 0.0, 0.02 * f.length);
}

TEST(FitDesign, TurnedMovedScaledCopyGivesTheSameDesign)
{
    const FitOptions o;
    const Mat3 turn =
        (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(2.1, Vec3::UnitX()))
            .toRotationMatrix();
    for (const ModelMesh& model : {house_model(), l_building_model(), truck_model()}) {
        const FitResult a = fitted(model, o);
        const FitResult b = fitted(moved(model, turn, 3.7, Vec3(120, -45, 1000)), o);
        ASSERT_EQ(a.mechanisms.size(), b.mechanisms.size()) << describe(a) << describe(b);
        for (size_t i = 0; i < a.mechanisms.size(); ++i) {
            EXPECT_EQ(a.mechanisms[i].kind_name(), b.mechanisms[i].kind_name());
            EXPECT_EQ(a.mechanisms[i].host, b.mechanisms[i].host);
            for (const auto& [k, v] : a.mechanisms[i].parameter_values())
                EXPECT_NEAR(b.mechanisms[i].parameter_values().at(k), v, 0.01 * 105)
                    << model.source << " " << a.mechanisms[i].name << " " << k;
        }
        // model_to_card of the copy, composed with the move, is the original's.
        Eigen::Matrix4d move = Eigen::Matrix4d::Identity();
        move.topLeftCorner<3, 3>() = 3.7 * turn;
        move.topRightCorner<3, 1>() = Vec3(120, -45, 1000);
        const Eigen::Matrix4d composed = b.model_to_card * move;
        for (const Vec3& v : model.vertices) {
            const Vec3 pa = (a.model_to_card * v.homogeneous()).head<3>();
            const Vec3 pb = (composed * v.homogeneous()).head<3>();
            EXPECT_LT((pa - pb).norm(), 0.01 * 105) << model.source;
        }
    }
}

TEST(FitDesign, UpAndFacingOverrideTheAlignment)
{
    // The cuboid lying on its side (its 30 along model x, 40 along model z): told which way is
    // up and which side faces the viewer, it comes back as the same box.
    const Mat3 lie = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
    FitOptions o;
    o.up = lie * Vec3::UnitZ();
    o.facing = lie * Vec3::UnitX();
    const FitResult r = fitted(moved(cuboid_model(), lie, 1.0, Vec3::Zero()), o);
    ASSERT_EQ(r.mechanisms.size(), 1u) << describe(r);
    const Frame f(120, 20, 30, o);
    EXPECT_UP(r.mechanisms[0].parameter_values().at("height"), 30, f);
    EXPECT_ACROSS(r.mechanisms[0].parameter_values().at("depth_ground"), 20, f);
    // model_to_card takes the given up to +z and facing to +x.
    const Mat3 linear = r.model_to_card.topLeftCorner<3, 3>();
    EXPECT_GT((linear * *o.up).normalized().z(), 0.999);
    EXPECT_GT((linear * *o.facing).normalized().x(), 0.999);
}

TEST(FitDesign, SameSeedSameDesign)
{
    FitOptions o;
    o.seed = 42;
    const FitResult a = fitted(truck_model(), o);
    const FitResult b = fitted(truck_model(), o);
    ASSERT_EQ(a.mechanisms.size(), b.mechanisms.size());
    for (size_t i = 0; i < a.mechanisms.size(); ++i)
        EXPECT_EQ(a.mechanisms[i].parameter_values(), b.mechanisms[i].parameter_values());
    EXPECT_EQ(a.ransac_draws, b.ransac_draws);
    EXPECT_EQ(a.model_to_card, b.model_to_card);
}

TEST(FitDesign, BadOptionsAreNamedWithTheirRange)
{
    FitOptions o;
    o.probability = 1.5;
    o.samples = 10;
    o.threshold = -1;
    const auto r = fit_design(cuboid_model(), o);
    EXPECT_FALSE(r.ok);
    std::vector<std::string> named;
    for (const auto& d : r.diagnostics) {
        EXPECT_EQ(d.code, DiagnosticCode::bad_option);
        named.push_back(d.parameter.value_or(""));
    }
    EXPECT_EQ(named, (std::vector<std::string>{"probability", "threshold", "samples"}));
    EXPECT_NE(r.diagnostics[0].message.find("1.5"), std::string::npos);
    EXPECT_NE(r.diagnostics[0].message.find("> 0 and < 1"), std::string::npos);

    FitOptions zero_up;
    zero_up.up = Vec3::Zero();
    const auto u = fit_design(cuboid_model(), zero_up);
    ASSERT_FALSE(u.ok);
    EXPECT_EQ(u.diagnostics[0].parameter.value_or(""), "up");

    FitOptions parallel;
    parallel.up = Vec3::UnitZ();
    parallel.facing = Vec3(0, 0, -2);
    const auto p = fit_design(cuboid_model(), parallel);
    ASSERT_FALSE(p.ok);
    EXPECT_EQ(p.diagnostics[0].parameter.value_or(""), "facing");
}

TEST(FitDesign, EmptyModelIsRefusedByName)
{
    ModelMesh empty;
    empty.source = "nothing.obj";
    const auto r = fit_design(empty, FitOptions());
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics[0].code, DiagnosticCode::empty_model);
}

TEST(FitDesign, CancelledBeforeItStartsThrowsCancelled)
{
    CancelFlag flag;
    flag.cancel();
    EXPECT_THROW(fit_design(cuboid_model(), FitOptions(), &flag), Cancelled);
}

TEST(FitDesign, LowAnnexesOnTheSidesAreStepFolds)
{
    const FitOptions o;
    const FitResult r = fitted(annexed_model(), o);
    ASSERT_EQ(r.mechanisms.size(), 3u) << describe(r);
    const Frame f(100, 35, 30, o);
    const FittedMechanism* box = find_type(r, "box_fold");
    ASSERT_TRUE(box) << describe(r);
    EXPECT_ACROSS(box->parameter_values().at("depth_ground"), 20, f);
    EXPECT_UP(box->parameter_values().at("height"), 30, f);
    int sides = 0;
    for (int k = 0; k < 2; ++k) {
        const FittedMechanism* step = find_type(r, "step_fold", k);
        ASSERT_TRUE(step) << describe(r);
        const auto& q = step->parameter_values();
        // On the ground side the page is the step's ground; on the backdrop side, the wall is.
        const bool ground_side = step->host == box->name + ".side_ground";
        EXPECT_TRUE(ground_side || step->host == box->name + ".side_backdrop") << step->host;
        sides += ground_side ? 1 : 2;
        EXPECT_ACROSS(q.at(ground_side ? "run_ground" : "run_backdrop"), 15, f);
        EXPECT_UP(q.at(ground_side ? "run_backdrop" : "run_ground"), 12, f);
        EXPECT_ALONG(q.at("width"), 50, f);
        // Which end of the box is y = 0 is the model's skew: the annex starts 20 from one end (and
        // ends 30 from the other).
        const double from_end = std::min(q.at("offset"), box->parameter_values().at("width") -
                                                             q.at("offset") - q.at("width"));
        EXPECT_ALONG(from_end, 20, f);
    }
    EXPECT_EQ(sides, 3);
}

/// Each mechanism's patches at the design state fill the box of the primitive it maps: the
/// mapping's geometry checked against what the generators built.
TEST(FitDesign, MechanismsBuildTheirPrimitives)
{
    for (const ModelMesh& model :
         {cuboid_model(), tent_model(), house_model(), truck_model(), annexed_model()}) {
        const FitResult r = fitted(model);
        for (const FittedMechanism& m : r.mechanisms) {
            const int index = std::stoi(m.primitive.substr(m.primitive.rfind(' ') + 1)) - 1;
            Eigen::AlignedBox3d expected, built;
            for (const Vec3& c : r.primitives.at(size_t(index)).corners)
                expected.extend(c);
            for (const Patch& p : r.scaffold.patches)
                if (p.name.rfind(m.name + ".", 0) == 0)
                    for (const Vec3& v : p.outer)
                        built.extend(v);
            const double tolerance = 1e-3 * expected.diagonal().norm();
            EXPECT_LT((built.min() - expected.min()).cwiseAbs().maxCoeff(), tolerance)
                << model.source << " " << m.name;
            EXPECT_LT((built.max() - expected.max()).cwiseAbs().maxCoeff(), tolerance)
                << model.source << " " << m.name;
        }
    }
}

/// Organic models (issue 12 §5): a valid design; every mechanism left out is reported twice, as
/// a repair and as a mechanism_dropped warning naming it.
TEST(FitDesign, OrganicModelsGiveValidDesignsAndReportWhatWasDropped)
{
    for (const ModelMesh& model : {figure_model(), blob_model()}) {
        const FitResult r = fitted(model);
        EXPECT_GE(r.mechanisms.size(), 1u) << model.source;
        EXPECT_LE(r.mechanisms.size(), 8u) << model.source;
        EXPECT_GT(r.coverage, 0.0) << model.source;
        int dropped = 0;
        for (const FitRepair& repair : r.repairs) {
            if (repair.action != "dropped" || repair.mechanism.rfind("primitive", 0) == 0)
                continue;
            ++dropped;
            bool warned = false;
            for (const Diagnostic& d : r.diagnostics)
                warned |= d.code == DiagnosticCode::mechanism_dropped &&
                          d.severity == Severity::warning &&
                          d.message.rfind(repair.mechanism + " ", 0) == 0;
            EXPECT_TRUE(warned) << repair.mechanism << ": " << repair.reason;
            for (const FittedMechanism& m : r.mechanisms)
                EXPECT_NE(m.name, repair.mechanism);
        }
        int warnings = 0;
        for (const Diagnostic& d : r.diagnostics)
            warnings += d.code == DiagnosticCode::mechanism_dropped;
        EXPECT_EQ(warnings, dropped) << model.source;
    }
}

/// Mean distance from the model's surface (spread here, area-weighted) to the pop-up at its
/// design state, divided by the model's diagonal: issue 12's goal for blocky models is under the
/// thesis's best mean, 0.0128, with at most 8 mechanisms.
TEST(FitDesign, BlockyModelsAreCloserThanTheThesisBestMean)
{
    for (const ModelMesh& model : {cuboid_model(), house_model(), truck_model(), tent_model(),
                                   l_building_model(), annexed_model()}) {
        const FitResult r = fitted(model);
        EXPECT_LE(r.mechanisms.size(), 8u);
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(0, 1);
        double total_area = 0;
        for (const auto& t : model.triangles)
            total_area += 0.5 * (model.vertices[t[1]] - model.vertices[t[0]])
                                    .cross(model.vertices[t[2]] - model.vertices[t[0]])
                                    .norm();
        double sum = 0;
        int n = 0;
        for (const auto& t : model.triangles) {
            const Vec3 a = model.vertices[t[0]], b = model.vertices[t[1]], c = model.vertices[t[2]];
            const double area = 0.5 * (b - a).cross(c - a).norm();
            const int count = int(std::ceil(3000 * area / total_area));
            for (int k = 0; k < count; ++k) {
                double x = u(rng), y = u(rng);
                if (x + y > 1) {
                    x = 1 - x;
                    y = 1 - y;
                }
                const Vec3 p = a + x * (b - a) + y * (c - a);
                const Vec3 q = (r.model_to_card * p.homogeneous()).head<3>();
                sum += distance_to_scaffold(r.scaffold, q);
                ++n;
            }
        }
        const double diagonal =
            r.model_to_card.topLeftCorner<3, 3>().col(0).norm() * model.diagonal();
        const double mean = sum / n / diagonal;
        std::printf("%-12s mechanisms %zu  mean model-to-pop-up / diagonal %.5f\n",
                    model.source.c_str(), r.mechanisms.size(), mean);
        EXPECT_LT(mean, 0.0128) << model.source;
    }
}

/// The L in plan of tools/make_models.py (a wing 60 x 20 along the front, an arm 20 x 50 to the
/// back, 30 high): no mirror plane, so the fold stands on the wing's back wall (y = 20), which
/// becomes the wing box's backbone. Two box folds side by side, each 20 deep on both sides of
/// the fold, and a step on the arm box's back side for the arm's last 10 behind it.
TEST(FitDesign, LInPlanIsTwoBoxesOnTheWingsBackWallAndAStep)
{
    FitOptions given;
    given.up = Vec3(0, 0, 1);
    given.facing = Vec3(0, -1, 0);
    for (const FitOptions& o : {given, FitOptions()}) {
        const FitResult r = fitted(l_plan_model(), o);
        ASSERT_EQ(r.mechanisms.size(), 3u) << describe(r);
        // Fold on y = 20: 20 in front, 30 behind; the card fits 60 long, 30 deep, 30 high.
        const double s = expected_scale(60, 30, 30, o);
        const double scale = r.model_to_card.block(0, 0, 3, 1).norm();
        EXPECT_NEAR(scale, s, 1e-9 * s);
        const double tol = 0.02 * std::sqrt(60 * 60 + 50 * 50 + 30 * 30) * s; // 2 % of diagonal
        const FittedMechanism *wing = nullptr, *arm = nullptr, *step = nullptr;
        for (const FittedMechanism& m : r.mechanisms) {
            if (m.kind_name() == "step_fold")
                step = &m;
            else if (m.kind_name() == "box_fold" && m.parameter_values().at("width") > 30 * s)
                wing = &m;
            else if (m.kind_name() == "box_fold")
                arm = &m;
        }
        ASSERT_TRUE(wing && arm && step) << describe(r);
        for (const FittedMechanism* box : {wing, arm}) {
            EXPECT_EQ(box->host, "central fold");
            EXPECT_NEAR(box->parameter_values().at("depth_ground"), 20 * s, tol) << box->name;
            EXPECT_NEAR(box->parameter_values().at("depth_backdrop"), 20 * s, tol) << box->name;
            EXPECT_NEAR(box->parameter_values().at("height"), 30 * s, tol) << box->name;
        }
        EXPECT_NEAR(wing->parameter_values().at("width"), 40 * s, tol);
        EXPECT_NEAR(arm->parameter_values().at("width"), 20 * s, tol);
        // Side by side along the fold: the arm at one end of the L's 60, the wing beyond it.
        const double arm_end =
            arm->parameter_values().at("offset") + arm->parameter_values().at("width");
        const double wing_end =
            wing->parameter_values().at("offset") + wing->parameter_values().at("width");
        EXPECT_NEAR(std::min(std::abs(arm_end - wing->parameter_values().at("offset")),
                             std::abs(wing_end - arm->parameter_values().at("offset"))),
                    0.0, tol);
        // The step stands on the arm's back wall (the backdrop side, or the ground side when
        // NPCA turns the card): 10 along the page, as tall as the wall (a step stops at 98 % of
        // its wall, the generator's bound).
        const bool behind = step->host == arm->name + ".side_backdrop";
        ASSERT_TRUE(behind || step->host == arm->name + ".side_ground") << describe(r);
        const auto& q = step->parameter_values();
        EXPECT_NEAR(q.at(behind ? "run_backdrop" : "run_ground"), 10 * s, tol);
        EXPECT_NEAR(q.at(behind ? "run_ground" : "run_backdrop"), 30 * s, tol);
        EXPECT_NEAR(step->parameter_values().at("width"), 20 * s, tol);
    }
}
