#include <gtest/gtest.h>

#include <cmath>

#include "popup/model/scaffold.hpp"
#include "test_support.hpp"

using namespace popup;

namespace {
bool has(const Result<Scaffold>& r, const std::string& code, const std::string& subject)
{
    for (const Diagnostic& d : r.diagnostics)
        if (to_string(d.code) == code && d.message.find(subject) != std::string::npos)
            return true;
    return false;
}
} // namespace

TEST(ScaffoldValidation, AcceptsAWellFormedCard)
{
    Scaffold s = fixtures::make_card();
    fixtures::add_tent_fold(s, 40, 60, 30, 40);
    const Result<Scaffold> r = validate_scaffold(s);
    EXPECT_TRUE(r.ok);
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_NEAR(r.value.patches[0].area(), 200.0 * 140.0, 1e-9);
    EXPECT_LT((r.value.patches[0].normal - Vec3::UnitZ()).norm(), 1e-15);
}

TEST(ScaffoldValidation, EmptyScaffoldIsRejected)
{
    const Result<Scaffold> r = validate_scaffold(Scaffold{});
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r, "empty_scaffold", "scaffold"));
}

TEST(ScaffoldValidation, NonPlanarPatchIsNamed)
{
    Scaffold s = fixtures::make_card();
    const int id = fixtures::add_quad(s, {10, 10, 0}, {20, 10, 0}, {20, 20, 3}, {10, 20, 0});
    const Result<Scaffold> r = validate_scaffold(s);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r, "non_planar_patch", "patch " + std::to_string(id)));
}

TEST(ScaffoldValidation, NaNAndInfinityAreNamed)
{
    Scaffold s = fixtures::make_card();
    s.patches[1].outer[2].y() = std::nan("");
    Result<Scaffold> r = validate_scaffold(s);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r, "non_finite_coordinate", "patch 1"));
    s = fixtures::make_card();
    s.patches[0].outer[0].x() = INFINITY;
    r = validate_scaffold(s);
    EXPECT_TRUE(has(r, "non_finite_coordinate", "patch 0"));
}

TEST(ScaffoldValidation, HingeOffItsPatchIsNamed)
{
    Scaffold s = fixtures::make_card();
    fixtures::add_tent_fold(s, 40, 60, 30, 40);
    s.hinges[1].to.y() += 25.0; // the foot hinge now runs past the slope's edge
    const Result<Scaffold> r = validate_scaffold(s);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(has(r, "hinge_off_patch", "hinge 1"));
}

TEST(ScaffoldValidation, MissingBasePatchAndBadIdsAreNamed)
{
    Scaffold s = fixtures::make_card();
    s.backdrop = 9;
    s.glue.push_back({0, 42});
    s.hinges.push_back({7, 0, 0, {0, 0, 0}, {0, 1, 0}});
    const Result<Scaffold> r = validate_scaffold(s);
    EXPECT_TRUE(has(r, "missing_base_patch", "backdrop"));
    EXPECT_TRUE(has(r, "bad_glue_patches", "glue[0]"));
    EXPECT_TRUE(has(r, "bad_hinge_patches", "hinge 7"));
}

TEST(ScaffoldValidation, AClosingRepeatIsDroppedAndOtherRepeatsAreNamed)
{
    Scaffold closed = fixtures::make_card();
    closed.patches[0].outer.push_back(closed.patches[0].outer.front()); // ring closed by repeat
    const Result<Scaffold> accepted = validate_scaffold(closed);
    ASSERT_TRUE(accepted.ok);
    EXPECT_EQ(accepted.value.patches[0].outer.size(), 4u);
    EXPECT_NEAR(accepted.value.patches[0].area(), 200.0 * 140.0, 1e-9);

    Scaffold twice = fixtures::make_card();
    Loop3& outer = twice.patches[0].outer;
    outer.insert(outer.begin() + 1, outer.front()); // vertices 0 and 1 at one point
    const Result<Scaffold> refused = validate_scaffold(twice);
    EXPECT_FALSE(refused.ok);
    ASSERT_EQ(refused.diagnostics.size(), 1u);
    const Diagnostic& d = refused.diagnostics.front();
    EXPECT_EQ(d.code, DiagnosticCode::repeated_vertex);
    EXPECT_EQ(d.patches, std::vector<int>{twice.patches[0].id});
    EXPECT_NE(d.message.find("as vertices 0 and 1"), std::string::npos) << d.message;

    Scaffold bow = fixtures::make_card(); // a vertex visited again later in the loop
    bow.patches[0].outer.push_back({70, 100, 0});
    bow.patches[0].outer.push_back({140, 200, 0});
    EXPECT_EQ(validate_scaffold(bow).diagnostics.front().code, DiagnosticCode::repeated_vertex);
}

TEST(ScaffoldValidation, CrossingOutlinesAndStrayHolesAreNamedWithWhere)
{
    // The ground (x 0..140, y 0..200 at z = 0) given a spike that folds back across its edge:
    // y = 170 + x/40 and y = 165 + x/10 cross each other at (66.6667, 171.667) and the edge
    // x = 140 at (140, 173.5) and (140, 179). The finding names one of them.
    Scaffold bow = fixtures::make_card();
    bow.patches[0].outer = {{0, 0, 0},   {140, 0, 0},   {140, 200, 0}, {0, 200, 0},
                            {0, 170, 0}, {200, 175, 0}, {200, 185, 0}, {0, 165, 0}};
    const Result<Scaffold> crossing = validate_scaffold(bow);
    ASSERT_FALSE(crossing.ok);
    const Diagnostic& d = crossing.diagnostics.front();
    EXPECT_EQ(d.code, DiagnosticCode::self_crossing_outline);
    EXPECT_EQ(d.patches, std::vector<int>{bow.patches[0].id});
    const bool named = d.message.find("at (66.6667, 171.667, 0)") != std::string::npos ||
                       d.message.find("at (140, 173.5, 0)") != std::string::npos ||
                       d.message.find("at (140, 179, 0)") != std::string::npos;
    EXPECT_TRUE(named) << d.message;

    auto with_hole = [](const Loop3& hole) {
        Scaffold s = fixtures::make_card();
        s.patches[0].holes = {hole};
        return validate_scaffold(s);
    };
    // Clockwise seen from above, as holes are.
    const Result<Scaffold> inside = with_hole({{20, 20, 0}, {20, 40, 0}, {40, 40, 0}, {40, 20, 0}});
    EXPECT_TRUE(inside.ok) << inside.diagnostics.front().message;
    const Result<Scaffold> outside =
        with_hole({{500, 500, 0}, {500, 600, 0}, {600, 600, 0}, {600, 500, 0}});
    ASSERT_FALSE(outside.ok);
    EXPECT_EQ(outside.diagnostics.front().code, DiagnosticCode::hole_outside_outline);
    const Result<Scaffold> across =
        with_hole({{120, 160, 0}, {120, 180, 0}, {160, 180, 0}, {160, 160, 0}});
    ASSERT_FALSE(across.ok);
    EXPECT_EQ(across.diagnostics.front().code, DiagnosticCode::hole_crosses_outline);
    EXPECT_NE(across.diagnostics.front().message.find("hole 1"), std::string::npos);
}

TEST(ScaffoldValidation, AFarCoordinateIsNamedNotCrashed)
{
    // 1e308 overflowed the frame and trapped inside GMP's exact numbers.
    Scaffold far = fixtures::make_card();
    far.patches[0].outer[1].x() = 1e308;
    const Result<Scaffold> r = validate_scaffold(far);
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::non_finite_coordinate);
    EXPECT_EQ(r.diagnostics.front().patches, std::vector<int>{far.patches[0].id});
}

TEST(ScaffoldValidation, AHoleTouchingTheOutlineAtAVertexIsNamed)
{
    Scaffold s = fixtures::make_card();
    s.patches[0].holes = {
        {{140, 20, 0}, {120, 10, 0}, {120, 30, 0}}}; // a corner on the x = 140 edge
    s.patches[0].outer.insert(s.patches[0].outer.begin() + 2, Vec3(140, 20, 0));
    const Result<Scaffold> r = validate_scaffold(s);
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::hole_crosses_outline);
    EXPECT_NE(r.diagnostics.front().message.find("(140, 20, 0)"), std::string::npos)
        << r.diagnostics.front().message;
}
