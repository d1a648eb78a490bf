// fit_metrics: distances, coverage and volume difference against integrals worked out by hand
// (docs/MATH.md, "Fit metrics").
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "popup/fitting/fit_metrics.hpp"

using namespace popup;

namespace {

/// The closed cuboid [lo, hi] as a ModelMesh, outward triangles.
ModelMesh cuboid_mesh(const Vec3& lo, const Vec3& hi)
{
    ModelMesh m;
    m.source = "cuboid";
    for (int i = 0; i < 8; ++i)
        m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                                i & 4 ? hi.z() : lo.z());
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

/// The faces of the box [lo, hi] as rectangles; the bottom (z = lo.z) only when asked.
std::vector<Loop3> box_faces(const Vec3& lo, const Vec3& hi, bool bottom)
{
    const double x0 = lo.x(), y0 = lo.y(), z0 = lo.z(), x1 = hi.x(), y1 = hi.y(), z1 = hi.z();
    std::vector<Loop3> faces = {
        {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, // top
        {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, // x = x0
        {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, // x = x1
        {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, // y = y0
        {{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}}, // y = y1
    };
    if (bottom)
        faces.push_back({{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}});
    return faces;
}

Scaffold scaffold_of(const std::vector<Loop3>& loops)
{
    Scaffold s;
    s.name = "hand-made pop-up";
    for (const Loop3& loop : loops) {
        Patch p;
        p.id = int(s.patches.size());
        p.name = "P" + std::to_string(p.id);
        p.outer = loop;
        s.patches.push_back(p);
    }
    return s;
}

/// A card 100 x 100 per page (ground x > 0, backdrop x < 0) with the shape's patches after.
Scaffold card_with(const std::vector<Loop3>& shape)
{
    std::vector<Loop3> loops = {{{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}},
                                {{-100, 0, 0}, {0, 0, 0}, {0, 100, 0}, {-100, 100, 0}}};
    loops.insert(loops.end(), shape.begin(), shape.end());
    Scaffold s = scaffold_of(loops);
    s.ground = 0;
    s.backdrop = 1;
    return s;
}

/// Model units are cm: the cuboid [0, 2] x [0, 3] x [0, 4] lands on [10, 30] x [20, 50] x [0, 40].
Eigen::Matrix4d centimetres_to_card()
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() *= 10.0;
    m.topRightCorner<3, 1>() = Vec3(10, 20, 0);
    return m;
}

std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi)
{
    std::vector<Vec3> c;
    for (int i = 0; i < 8; ++i)
        c.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    return c;
}

const double kDiagonal = std::sqrt(20.0 * 20 + 30 * 30 + 40 * 40);

} // namespace

TEST(FitMetrics, TwoCuboidsOffsetByThreeMillimetres)
{
    // Model [0,20]x[0,30]x[0,40]; pop-up: the same box moved 3 mm along x. Per face of the
    // model, distance to the other box: x = 0 face 3; x = 20 face min(3, distance to its
    // border), integral ∫0^3 (30-2t)(40-2t) dt = 3006; y faces ∫0^3 (3-x) dx * 40 = 180 each;
    // z faces 4.5 * 30 = 135 each. Total 7236 over 5200 mm². Squares: 10800 + 8442 + 2*360 +
    // 2*270 = 20502. By symmetry the other way is the same.
    const ModelMesh model = cuboid_mesh(Vec3(0, 0, 0), Vec3(20, 30, 40));
    const Scaffold popup = scaffold_of(box_faces(Vec3(3, 0, 0), Vec3(23, 30, 40), true));
    FitMetricsOptions options;
    options.samples = 200000;
    options.threshold_mm = 0.0;
    const Result<FitMetrics> r =
        fit_metrics(model, Eigen::Matrix4d::Identity(), popup, {}, options);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    const FitMetrics& m = r.value;
    EXPECT_NEAR(m.diagonal_mm, kDiagonal, 1e-9);
    const double tolerance = options.hausdorff_error * kDiagonal;
    for (const DistanceStats& s : {m.model_to_popup_mm, m.popup_to_model_mm}) {
        EXPECT_NEAR(s.max, 3.0, tolerance);
        EXPECT_NEAR(s.mean, 7236.0 / 5200.0, 0.02);
        EXPECT_NEAR(s.rms, std::sqrt(20502.0 / 5200.0), 0.02);
    }
    EXPECT_NEAR(m.model_to_popup.mean, m.model_to_popup_mm.mean / kDiagonal, 1e-12);
    EXPECT_NEAR(m.popup_to_model.max, m.popup_to_model_mm.max / kDiagonal, 1e-12);
    EXPECT_TRUE(m.model_closed);
    EXPECT_NEAR(m.volume_difference, 1.0, 1e-12) << "no prisms: all of the model differs";
}

TEST(FitMetrics, ABoxFoldTallerThanItsCuboidOnACard)
{
    // The model (in cm) stands on the ground page; the pop-up is the card plus a box 4 mm
    // taller, without a bottom. Model to pop-up: only the model's top is off, by
    // min(4, distance to the top's border): ∫0^4 (20-2t)(30-2t) dt = 1685.33, squares
    // ∫0^4 2t(20-2t)(30-2t) dt = 5845.33, over 5200 mm². Within 1 mm: all but the top's inner
    // 18 x 28. Pop-up to model (without the pages): the walls' top 4 mm at z - 40, the lid at 4.
    const ModelMesh model = cuboid_mesh(Vec3(0, 0, 0), Vec3(2, 3, 4));
    const Scaffold popup = card_with(box_faces(Vec3(10, 20, 0), Vec3(30, 50, 44), false));
    FitMetricsOptions options;
    options.samples = 200000;
    options.threshold_mm = 1.0;
    const std::vector<std::vector<Vec3>> prisms = {box_corners(Vec3(10, 20, 0), Vec3(30, 50, 44))};
    const Result<FitMetrics> r = fit_metrics(model, centimetres_to_card(), popup, prisms, options);
    ASSERT_TRUE(r.ok) << r.diagnostics.front().message;
    const FitMetrics& m = r.value;
    const double tolerance = options.hausdorff_error * kDiagonal;
    EXPECT_NEAR(m.diagonal_mm, kDiagonal, 1e-9);
    EXPECT_NEAR(m.model_to_popup_mm.max, 4.0, tolerance);
    EXPECT_NEAR(m.model_to_popup_mm.mean, 1685.3333 / 5200.0, 0.01);
    EXPECT_NEAR(m.model_to_popup_mm.rms, std::sqrt(5845.3333 / 5200.0), 0.01);
    EXPECT_NEAR(m.coverage, (5200.0 - 18.0 * 28.0) / 5200.0, 0.005);
    EXPECT_NEAR(m.popup_to_model_mm.max, 4.0, tolerance);
    EXPECT_NEAR(m.popup_to_model_mm.mean, 3200.0 / 5000.0, 0.02);
    EXPECT_NEAR(m.popup_to_model_mm.rms, std::sqrt(11733.333 / 5000.0), 0.02);
    EXPECT_NEAR(m.model_to_popup.max, 4.0 / kDiagonal, tolerance / kDiagonal);
    // Volume: the prism is 20 x 30 x 44, the model 20 x 30 x 40: 2400 / 24000.
    EXPECT_TRUE(m.model_closed);
    EXPECT_NEAR(m.model_volume_mm3, 24000.0, 1e-6);
    EXPECT_NEAR(m.volume_difference, 0.1, 0.01);
    EXPECT_NEAR(m.popup_volume_mm3, 26400.0, 0.02 * 26400.0);
}

TEST(FitMetrics, VolumeDifferenceOfACuboidWithItselfAndWithItsLowerHalf)
{
    const ModelMesh model = cuboid_mesh(Vec3(0, 0, 0), Vec3(2, 3, 4));
    const Scaffold popup = card_with(box_faces(Vec3(10, 20, 0), Vec3(30, 50, 40), false));
    const Result<FitMetrics> same = fit_metrics(model, centimetres_to_card(), popup,
                                                {box_corners(Vec3(10, 20, 0), Vec3(30, 50, 40))});
    ASSERT_TRUE(same.ok);
    EXPECT_NEAR(same.value.volume_difference, 0.0, 1e-12);
    EXPECT_NEAR(same.value.model_to_popup_mm.max, 0.0, 1e-3 * kDiagonal);
    EXPECT_NEAR(same.value.coverage, 1.0, 1e-12);
    // The lower half, split in two prisms that overlap: the union counts once.
    const Result<FitMetrics> half = fit_metrics(model, centimetres_to_card(), popup,
                                                {box_corners(Vec3(10, 20, 0), Vec3(30, 40, 20)),
                                                 box_corners(Vec3(10, 30, 0), Vec3(30, 50, 20))});
    ASSERT_TRUE(half.ok);
    EXPECT_NEAR(half.value.volume_difference, 0.5, 1e-12);
    EXPECT_NEAR(half.value.popup_volume_mm3, 12000.0, 1e-6);
    // A triangular prism: half the box cut along its diagonal plane x/20 + z/40 = 1.
    const Result<FitMetrics> wedge =
        fit_metrics(model, centimetres_to_card(), popup,
                    {{Vec3(10, 20, 0), Vec3(30, 20, 0), Vec3(10, 20, 40), Vec3(10, 50, 0),
                      Vec3(30, 50, 0), Vec3(10, 50, 40)}});
    ASSERT_TRUE(wedge.ok);
    EXPECT_NEAR(wedge.value.volume_difference, 0.5, 0.02);
}

TEST(FitMetrics, PatchHolesAreNotPaper)
{
    // A flat 40 x 40 model on a 40 x 40 patch with a 10 x 20 hole: 200 of 1600 mm² uncovered.
    ModelMesh model;
    model.vertices = {Vec3(0, 0, 0), Vec3(40, 0, 0), Vec3(40, 40, 0), Vec3(0, 40, 0)};
    model.triangles = {{0, 1, 2}, {0, 2, 3}};
    Scaffold popup = scaffold_of({{{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}}});
    popup.patches[0].holes = {{{10, 10, 0}, {10, 30, 0}, {20, 30, 0}, {20, 10, 0}}};
    FitMetricsOptions options;
    options.samples = 100000;
    options.threshold_mm = 0.0;
    const Result<FitMetrics> r =
        fit_metrics(model, Eigen::Matrix4d::Identity(), popup, {}, options);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.value.coverage, 1.0 - 200.0 / 1600.0, 0.005);
    // Farthest from paper: the hole's centre line, 5 mm from its long sides.
    EXPECT_NEAR(r.value.model_to_popup_mm.max, 5.0, 1e-3 * r.value.diagonal_mm);
    EXPECT_NEAR(r.value.popup_to_model_mm.max, 0.0, 1e-3 * r.value.diagonal_mm);
    EXPECT_FALSE(r.value.model_closed);
    EXPECT_TRUE(std::isnan(r.value.volume_difference));
    EXPECT_TRUE(std::isnan(r.value.model_volume_mm3));
}

TEST(FitMetrics, TheSameSeedGivesTheSameNumbers)
{
    const ModelMesh model = cuboid_mesh(Vec3(0, 0, 0), Vec3(2, 3, 4));
    const Scaffold popup = card_with(box_faces(Vec3(10, 20, 0), Vec3(30, 50, 44), false));
    FitMetricsOptions options;
    options.samples = 5000;
    options.seed = 7;
    const auto a = fit_metrics(model, centimetres_to_card(), popup, {}, options).value;
    const auto b = fit_metrics(model, centimetres_to_card(), popup, {}, options).value;
    options.seed = 8;
    const auto c = fit_metrics(model, centimetres_to_card(), popup, {}, options).value;
    EXPECT_EQ(a.model_to_popup_mm.mean, b.model_to_popup_mm.mean);
    EXPECT_EQ(a.popup_to_model_mm.rms, b.popup_to_model_mm.rms);
    EXPECT_EQ(a.coverage, b.coverage);
    EXPECT_NE(a.model_to_popup_mm.mean, c.model_to_popup_mm.mean);
}

TEST(FitMetrics, BadInputsAreNamed)
{
    const ModelMesh model = cuboid_mesh(Vec3(0, 0, 0), Vec3(2, 3, 4));
    const Scaffold popup = card_with(box_faces(Vec3(10, 20, 0), Vec3(30, 50, 40), false));
    auto first = [](const Result<FitMetrics>& r) { return r.diagnostics.front(); };

    const auto flat = fit_metrics(model, centimetres_to_card(), popup,
                                  {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}});
    ASSERT_FALSE(flat.ok);
    EXPECT_EQ(first(flat).code, DiagnosticCode::bad_option);
    EXPECT_NE(first(flat).message.find("prisms[0]"), std::string::npos) << first(flat).message;

    Eigen::Matrix4d bad = centimetres_to_card();
    bad(1, 2) = std::nan("");
    const auto nan = fit_metrics(model, bad, popup, {});
    ASSERT_FALSE(nan.ok);
    EXPECT_EQ(first(nan).parameter, std::optional<std::string>("model_to_card"));

    FitMetricsOptions options;
    options.samples = 0;
    const auto none = fit_metrics(model, centimetres_to_card(), popup, {}, options);
    ASSERT_FALSE(none.ok);
    EXPECT_NE(first(none).message.find("samples = 0"), std::string::npos);

    const auto only_card = fit_metrics(model, centimetres_to_card(), card_with({}), {});
    ASSERT_FALSE(only_card.ok);
    EXPECT_EQ(first(only_card).code, DiagnosticCode::empty_scaffold);

    ModelMesh empty = model;
    empty.triangles.clear();
    const auto no_faces = fit_metrics(empty, centimetres_to_card(), popup, {});
    ASSERT_FALSE(no_faces.ok);
    EXPECT_EQ(first(no_faces).code, DiagnosticCode::empty_model);
}
