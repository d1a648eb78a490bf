// BREP export: read the text back with OCCT and measure it (faces, validity, area, volume,
// bounding box, orientation), plus the errors bad input must raise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "popup/io/brep_export.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "test_support.hpp"

// OCCT 7.6 headers derive from the deprecated std::iterator.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Plane.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shape.hxx>
#pragma GCC diagnostic pop

namespace {

using namespace popup;
using namespace popup::fixtures;

TopoDS_Shape read_brep(const std::string& text)
{
    std::istringstream in(text);
    TopoDS_Shape shape;
    BRep_Builder builder;
    BRepTools::Read(shape, in, builder);
    return shape;
}

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type)
{
    int n = 0;
    for (TopExp_Explorer ex(shape, type); ex.More(); ex.Next())
        ++n;
    return n;
}

double surface_area(const TopoDS_Shape& shape)
{
    GProp_GProps props;
    BRepGProp::SurfaceProperties(shape, props);
    return props.Mass();
}

double volume(const TopoDS_Shape& shape)
{
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    return props.Mass();
}

struct Box {
    Vec3 min, max;
};

Box bounding_box(const TopoDS_Shape& shape)
{
    Bnd_Box box;
    // Optimal and without the tolerance gap, so the numbers can be compared tightly.
    BRepBndLib::AddOptimal(shape, box, Standard_False, Standard_False);
    Box b;
    box.Get(b.min.x(), b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z());
    return b;
}

double total_area(const Scaffold& s)
{
    double a = 0.0;
    for (const Patch& p : s.patches)
        a += p.area();
    return a;
}

Scaffold validated(Scaffold s)
{
    Result<Scaffold> r = validate_scaffold(std::move(s));
    for (const Diagnostic& d : r.diagnostics)
        ADD_FAILURE() << to_string(d.code) << ": " << d.message;
    return r.value;
}

// Card 200 x 140 (56000 mm²) + tent (two 35 x 40 slopes, 2800 mm²) + step (riser 20 x 40 and
// tread 30 x 40, 2000 mm²): 60800 mm² in 6 patches.
constexpr double kFoldedCardArea = 60800.0;

Scaffold card_with_folds()
{
    Scaffold s = make_card(200.0, 140.0);
    add_tent_fold(s, 20.0, 40.0, 20.0, 35.0);
    add_step_fold(s, 100.0, 40.0, 30.0, 20.0);
    return validated(std::move(s));
}

template <class E, class F> std::string message_of(F&& f)
{
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an exception";
    return {};
}

std::string id_of(const Patch& p)
{
    return "patch " + std::to_string(p.id);
}

TEST(BrepExport, DesignStateHasOneValidFacePerPatchAndTheirArea)
{
    const Scaffold s = card_with_folds();
    ASSERT_EQ(s.patches.size(), 6u);
    const TopoDS_Shape shape = read_brep(design_to_brep(s));
    ASSERT_FALSE(shape.IsNull());
    EXPECT_EQ(shape.ShapeType(), TopAbs_COMPOUND);
    EXPECT_EQ(count(shape, TopAbs_FACE), 6);
    EXPECT_EQ(count(shape, TopAbs_SOLID), 0);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    EXPECT_NEAR(surface_area(shape), total_area(s), 1e-6);
    EXPECT_NEAR(surface_area(shape), kFoldedCardArea, 1e-6);
}

TEST(BrepExport, FaceNormalsAreThePatchNormals)
{
    // The printed side must survive the export: FreeCAD shades and offsets by face normal.
    const Scaffold s = card_with_folds();
    const TopoDS_Shape shape = read_brep(design_to_brep(s));
    std::size_t i = 0;
    for (TopoDS_Iterator it(shape); it.More(); it.Next(), ++i) {
        ASSERT_LT(i, s.patches.size());
        const TopoDS_Face face = TopoDS::Face(it.Value());
        Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face));
        ASSERT_FALSE(plane.IsNull()) << "face " << i << " is not planar";
        gp_Dir d = plane->Axis().Direction();
        if (face.Orientation() == TopAbs_REVERSED)
            d.Reverse();
        const Vec3& n = s.patches[i].normal;
        EXPECT_NEAR(d.X() * n.x() + d.Y() * n.y() + d.Z() * n.z(), 1.0, 1e-9)
            << "patch " << s.patches[i].id;
    }
    EXPECT_EQ(i, s.patches.size());
}

TEST(BrepExport, PosedCardBoundingBoxFollowsTheRotation)
{
    // Ground x in [0, 140], backdrop x in [-140, 0], y in [0, 200], z = 0. Rotated 90° about z,
    // (x, y) -> (-y, x), then shifted by (10, 20, 30).
    const Scaffold s = validated(make_card(200.0, 140.0));
    FoldState state;
    Pose pose;
    pose.rotation = axis_angle(Vec3::UnitZ(), deg(90.0));
    pose.translation = Vec3(10.0, 20.0, 30.0);
    state.poses.assign(s.patches.size(), pose);
    const TopoDS_Shape shape = read_brep(patches_to_brep(s, state));
    EXPECT_EQ(count(shape, TopAbs_FACE), 2);
    const Box b = bounding_box(shape);
    EXPECT_NEAR(b.min.x(), -190.0, 1e-6);
    EXPECT_NEAR(b.max.x(), 10.0, 1e-6);
    EXPECT_NEAR(b.min.y(), -120.0, 1e-6);
    EXPECT_NEAR(b.max.y(), 160.0, 1e-6);
    EXPECT_NEAR(b.min.z(), 30.0, 1e-6);
    EXPECT_NEAR(b.max.z(), 30.0, 1e-6);
    EXPECT_NEAR(surface_area(shape), 56000.0, 1e-6);
}

TEST(BrepExport, SimulatedStateMatchesPosedVerticesAndKeepsArea)
{
    const Scaffold s = card_with_folds();
    const Result<FoldSweep> sweep = simulate_fold(s, {deg(90.0)});
    ASSERT_TRUE(sweep.ok);
    ASSERT_EQ(sweep.value.states.size(), 1u);
    const FoldState& state = sweep.value.states[0];

    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for (std::size_t i = 0; i < s.patches.size(); ++i)
        for (const Vec3& p : s.patches[i].outer) {
            const Vec3 w = state.poses[i].apply(p);
            lo = lo.cwiseMin(w);
            hi = hi.cwiseMax(w);
        }
    const TopoDS_Shape shape = read_brep(patches_to_brep(s, state));
    EXPECT_EQ(count(shape, TopAbs_FACE), 6);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    // Poses are rigid, so the area is the design area; vertices are projected onto the patch
    // plane, which moves them by no more than the simulator's residual.
    EXPECT_NEAR(surface_area(shape), kFoldedCardArea, 1e-3);
    const Box b = bounding_box(shape);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.min[k], lo[k], 1e-5) << "axis " << k;
        EXPECT_NEAR(b.max[k], hi[k], 1e-5) << "axis " << k;
    }
    // Thesis frame: z bisects the fold angle, so at 90° each 140 mm base patch leans 45° from z
    // and the pop-ups stay between them.
    const double r = 140.0 * std::cos(kPi / 4.0);
    EXPECT_NEAR(b.min.x(), -r, 1e-6);
    EXPECT_NEAR(b.max.x(), r, 1e-6);
    EXPECT_NEAR(b.min.y(), 0.0, 1e-6);
    EXPECT_NEAR(b.max.y(), 200.0, 1e-6);
    EXPECT_NEAR(b.min.z(), 0.0, 1e-6);
    EXPECT_NEAR(b.max.z(), r, 1e-6);
}

TEST(BrepExport, ThicknessGivesCentredSolidsOfAreaTimesThickness)
{
    const Scaffold s = card_with_folds();
    BrepOptions options;
    options.thickness = 0.2;
    const TopoDS_Shape shape = read_brep(design_to_brep(s, options));
    EXPECT_EQ(count(shape, TopAbs_SOLID), 6);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    double v = 0.0;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) {
        const double vi = volume(ex.Current());
        EXPECT_GT(vi, 0.0) << "solids must be outward-oriented";
        v += vi;
    }
    EXPECT_NEAR(v, kFoldedCardArea * 0.2, 1e-6);

    // The flat card alone: paper centred on z = 0.
    const TopoDS_Shape card = read_brep(design_to_brep(validated(make_card()), options));
    const Box b = bounding_box(card);
    EXPECT_NEAR(b.min.z(), -0.1, 1e-9);
    EXPECT_NEAR(b.max.z(), 0.1, 1e-9);
}

TEST(BrepExport, HolesAreCutWhicheverWayTheyWind)
{
    for (bool clockwise : {true, false}) {
        Scaffold s = make_card(200.0, 140.0);
        const int ground = s.patch_index(s.ground);
        ASSERT_GE(ground, 0);
        // 20 x 30 window in the ground.
        Loop3 hole = {{50, 60, 0}, {70, 60, 0}, {70, 90, 0}, {50, 90, 0}};
        const Vec3 n = s.patches[ground].normal;
        const bool ccw_about_n = n.z() > 0.0;
        if (ccw_about_n == clockwise)
            std::reverse(hole.begin(), hole.end());
        s.patches[ground].holes.push_back(hole);
        s = validated(std::move(s));

        const TopoDS_Shape shape = read_brep(design_to_brep(s));
        EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid()) << "clockwise " << clockwise;
        EXPECT_EQ(count(shape, TopAbs_WIRE), 3);
        EXPECT_NEAR(surface_area(shape), 56000.0 - 600.0, 1e-6) << "clockwise " << clockwise;

        BrepOptions options;
        options.thickness = 0.5;
        const TopoDS_Shape solid = read_brep(design_to_brep(s, options));
        EXPECT_TRUE(BRepCheck_Analyzer(solid).IsValid());
        EXPECT_NEAR(volume(solid), (56000.0 - 600.0) * 0.5, 1e-6);
    }
}

TEST(BrepExport, WrongPoseCountThrows)
{
    const Scaffold s = card_with_folds();
    FoldState state;
    state.poses.assign(s.patches.size() - 1, Pose{});
    const std::string msg = message_of<std::invalid_argument>([&] { patches_to_brep(s, state); });
    EXPECT_NE(msg.find("5 poses for 6 patches"), std::string::npos) << msg;
}

TEST(BrepExport, NonFiniteVertexThrowsNamingThePatch)
{
    Scaffold s = card_with_folds();
    Patch& p = s.patches[3];
    p.name = "slope-left";
    p.outer[1].x() = std::numeric_limits<double>::quiet_NaN();
    const std::string msg = message_of<std::invalid_argument>([&] { design_to_brep(s); });
    EXPECT_NE(msg.find(id_of(p)), std::string::npos) << msg;
    EXPECT_NE(msg.find("slope-left"), std::string::npos) << msg;
    EXPECT_NE(msg.find("non-finite"), std::string::npos) << msg;
}

TEST(BrepExport, NonFinitePoseThrowsNamingThePatch)
{
    const Scaffold s = card_with_folds();
    FoldState state;
    state.poses.assign(s.patches.size(), Pose{});
    state.poses[4].translation.y() = std::numeric_limits<double>::infinity();
    const std::string msg = message_of<std::invalid_argument>([&] { patches_to_brep(s, state); });
    EXPECT_NE(msg.find(id_of(s.patches[4])), std::string::npos) << msg;
}

TEST(BrepExport, TooFewVerticesThrowsNamingThePatch)
{
    Scaffold s = card_with_folds();
    s.patches[2].outer.resize(2);
    const std::string msg = message_of<std::invalid_argument>([&] { design_to_brep(s); });
    EXPECT_NE(msg.find(id_of(s.patches[2])), std::string::npos) << msg;
    EXPECT_NE(msg.find("at least 3"), std::string::npos) << msg;

    // A closing vertex repeating the first does not count as a third.
    s.patches[2].outer.push_back(s.patches[2].outer.front());
    EXPECT_THROW(design_to_brep(s), std::invalid_argument);
}

TEST(BrepExport, SelfIntersectingOutlineFailsTheCheckNamingThePatch)
{
    // A bow-tie whose lobes differ in size: it has a normal, but BRepCheck rejects the wire.
    Scaffold s = card_with_folds();
    Patch& p = s.patches[1];
    p.outer = {{0, 0, 0}, {-20, 0, 0}, {0, 10, 0}, {-10, 10, 0}};
    p.holes.clear();
    const std::string msg = message_of<std::runtime_error>([&] { design_to_brep(s); });
    EXPECT_NE(msg.find(id_of(p)), std::string::npos) << msg;
    EXPECT_NE(msg.find("BRepCheck"), std::string::npos) << msg;
}

TEST(BrepExport, NegativeThicknessThrows)
{
    BrepOptions options;
    options.thickness = -0.1;
    EXPECT_THROW(design_to_brep(card_with_folds(), options), std::invalid_argument);
}

} // namespace
