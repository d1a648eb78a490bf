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
