// design_motion's outlines (thesis §6.4, Patches) on a rig built here: a body and an arm, each a
// box skinned to one bone; the arm's bone follows the horizontal translation's closed form. The
// arm's moving patch must end as the arm's posed box (projected on the card) clipped to the
// patch, with the area derived here by clipping the unprofiled patch to that rectangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "motion/motion_outlines.hpp"
#include "motion_fixtures.hpp"
#include "popup/motion/design_motion.hpp"
#include "popup/motion/printed_parts.hpp"
#include "popup/refers_into_argument.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup::motion {
namespace {

Eigen::Isometry3d at(const Vec3& t)
{
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    m.translation() = t;
    return m;
}

/// The 8 corners and 12 triangles (outward) of an axis-aligned box, appended to `mesh`.
void add_box(ModelMesh& mesh, const Vec3& lo, const Vec3& hi)
{
    const int base = int(mesh.vertices.size());
    for (int k = 0; k < 8; ++k)
        mesh.vertices.push_back(
            Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        mesh.triangles.push_back({base + f[0], base + f[1], base + f[2]});
        mesh.triangles.push_back({base + f[0], base + f[2], base + f[3]});
    }
}

const Vec3 body_origin(0, 150, 0);
// At the last frame (the card open flat) the arm lies over x in [-3, 40] and y in [45, 85]: it
// covers the moving patch's whole width (the fold it is glued on stays whole) and 40 mm of its
// 60 mm reach.
const Vec3 arm_lo(-3, 45, -2), arm_hi(40, 85, 2);

/// Bones body (root), arm and head, a box each; the arm's origin
/// follows the sample horizontal translation's point; the mesh is authored at the last frame.
Animation rig()
{
    const MotionMechanism h = testing::sample_mechanism(MotionKind::horizontal);
    Animation a;
    a.source = "box rig";
    a.bones = {{"body", -1}, {"arm", 0}, {"head", 0}};
    const int frames = 31;
    for (int f = 0; f < frames; ++f) {
        a.frame_times_s.push_back(f / 30.0);
        const Vec3 tip = mechanism_point(h, M_PI * f / (frames - 1));
        a.local.push_back(
            {at(body_origin), at(Vec3(tip.x(), tip.y(), 0) - body_origin), at(Vec3(0, 20, 0))});
    }
    const Vec3 tip_open = mechanism_point(h, M_PI);
    add_box(a.mesh, Vec3(-20, 120, -5), Vec3(20, 175, 5)); // body
    add_box(a.mesh, arm_lo, arm_hi);                       // arm
    add_box(a.mesh, Vec3(-8, 175, -4), Vec3(8, 190, 4));   // head
    a.bind_inverse = {at(body_origin).inverse(), at(Vec3(tip_open.x(), tip_open.y(), 0)).inverse(),
                      at(body_origin + Vec3(0, 20, 0)).inverse()};
    for (int v = 0; v < 24; ++v)
        a.skin.push_back({{v / 8, 1.0}});
    return a;
}

/// Card placement 1:1 (scale 1, the character's box centre where it is): card = file (x, y).
MotionOptions options_for(const Animation& a)
{
    Eigen::AlignedBox3d box;
    for (int f = 0; f < a.frames(); ++f) {
        for (const Eigen::Isometry3d& g : forward_kinematics(a, f))
            box.extend(g.translation());
        for (const Vec3& v : posed_mesh(a, f).vertices)
            box.extend(v);
    }
    MotionOptions o;
    o.view.scale = 1.0;
    o.view.centre = box.center().head<2>();
    o.iterations = 300;
    return o;
}

/// Sutherland–Hodgman: the convex polygon `poly` (x, y) clipped to [lo, hi].
std::vector<Vec2> clip_to_rectangle(std::vector<Vec2> poly, const Vec2& lo, const Vec2& hi)
{
    for (int side = 0; side < 4; ++side) {
        const int axis = side % 2;
        const double bound = side < 2 ? lo[axis] : hi[axis];
        auto inside = [&](const Vec2& p) { return side < 2 ? p[axis] >= bound : p[axis] <= bound; };
        std::vector<Vec2> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const Vec2 &p = poly[k], &q = poly[(k + 1) % poly.size()];
            if (inside(p))
                out.push_back(p);
            if (inside(p) != inside(q)) {
                const double t = (bound - p[axis]) / (q[axis] - p[axis]);
                out.push_back(p + t * (q - p));
            }
        }
        poly = out;
    }
    return poly;
}

double area_of(const std::vector<Vec2>& poly)
{
    double a = 0;
    for (std::size_t k = 0; k < poly.size(); ++k)
        a += poly[k].x() * poly[(k + 1) % poly.size()].y() -
             poly[(k + 1) % poly.size()].x() * poly[k].y();
    return std::abs(a) / 2;
}

POPUP_REFERS_INTO_ARGUMENT const ChainReport& chain_named(const MotionResult& r,
                                                          const std::string& name)
{
    for (const ChainReport& c : r.chains)
        if (c.name == name)
            return c;
    throw std::runtime_error("no chain " + name);
}

} // namespace

TEST(MotionOutlines, TheArmsPatchIsItsPosedBoxClippedToThePatch)
{
    const Animation a = rig();
    MotionOptions o = options_for(a);
    o.outlines = false;
    const Result<MotionResult> plain = design_motion(a, o);
    o.outlines = true;
    const Result<MotionResult> outlined = design_motion(a, o);
    ASSERT_TRUE(plain.ok && outlined.ok);
    const MotionResult& r = outlined.value;
    // The placement is 1:1, so the box's card rectangle is the authored one.
    EXPECT_NEAR(r.targets.animation_to_card(0, 0), 1.0, 1e-12);
    const ChainReport& arm = chain_named(r, "arm");
    ASSERT_EQ(arm.status, "animated") << arm.reason;
    ASSERT_EQ(arm.mapping, "horizontal");
    ASSERT_FALSE(arm.mechanisms.empty());
    const std::string mech = arm.mechanisms.front();
    const FittedProfile* profile = nullptr;
    for (const FittedProfile& p : r.profiles)
        if (p.mechanism == mech && p.part == "M")
            profile = &p;
    ASSERT_NE(profile, nullptr) << "no outline on " << mech << ".M";
    // The patch as generated (the run without outlines builds the same design: same seed).
    const Patch* before = nullptr;
    for (const Patch& p : plain.value.scaffold.patches)
        if (p.name == mech + ".M")
            before = &p;
    ASSERT_NE(before, nullptr);
    std::vector<Vec2> poly;
    for (const Vec3& x : before->outer) {
        EXPECT_NEAR(x.z(), 0.0, 1e-9); // flat on the card at 180°: its projection is itself
        poly.push_back(x.head<2>());
    }
    const double expected = area_of(clip_to_rectangle(poly, arm_lo.head<2>(), arm_hi.head<2>()));
    // By hand: M lies from the fold (x = 0) to the reach, 60 mm for the rig's mechanism (fitted
    // within 1 %), across a width inside the box's band: the box keeps 40 mm of its length.
    double y_lo = poly.front().y(), y_hi = y_lo;
    for (const Vec2& q : poly) {
        y_lo = std::min(y_lo, q.y());
        y_hi = std::max(y_hi, q.y());
    }
    ASSERT_GT(y_lo, arm_lo.y());
    ASSERT_LT(y_hi, arm_hi.y());
    EXPECT_NEAR(expected, 40.0 * (y_hi - y_lo), 1e-6);
    ASSERT_GT(expected, 1.0);
    ASSERT_LT(expected, area_of(poly) - 1.0); // the box does cut the patch
    EXPECT_NEAR(profile->area, expected, 1e-3);
    EXPECT_NEAR(profile->area_before, area_of(poly), 1e-3);
    const Patch* after = nullptr;
    for (const Patch& p : r.scaffold.patches)
        if (p.name == mech + ".M")
            after = &p;
    ASSERT_NE(after, nullptr);
    std::vector<Vec2> cut;
    for (const Vec3& x : after->outer)
        cut.push_back(x.head<2>());
    EXPECT_NEAR(area_of(cut), expected, 1e-3);
    EXPECT_TRUE(r.valid);
    EXPECT_TRUE(check_validity(r.scaffold).valid());
}

TEST(MotionOutlines, WithoutAMeshTheReportSaysThereIsNoOutline)
{
    Animation a = rig();
    MotionOptions o = options_for(a);
    a.mesh = ModelMesh{};
    a.skin.clear();
    a.bind_inverse.assign(a.bones.size(), Eigen::Isometry3d::Identity());
    const Result<MotionResult> r = design_motion(a, o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.profiles.empty());
    const bool said = std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [](const auto& d) {
        return d.code == DiagnosticCode::empty_model && d.severity == Severity::warning &&
               d.message.find("no skinned mesh") != std::string::npos;
    });
    EXPECT_TRUE(said);
}

// printed_parts on the same rig: the arm's box is the limb on the horizontal translation's M,
// the body box (and the head, unless a floating layer carries it) the body; each box's posed
// corners are the authored ones (the mesh is authored at the last frame and the placement is 1:1),
// so the split is checked against the boxes as written above.
TEST(PrintedParts, TheArmIsPrintedOnItsMechanismAndTheBodyWithoutIt)
{
    const Animation a = rig();
    const Result<MotionResult> r = design_motion(a, options_for(a));
    ASSERT_TRUE(r.ok);
    const ChainReport& arm = chain_named(r.value, "arm");
    ASSERT_EQ(arm.status, "animated") << arm.reason;
    const std::vector<PrintedPart> printed = printed_parts(a, r.value);
    ASSERT_GE(printed.size(), 2u);
    const PrintedPart& body = printed[0];
    EXPECT_TRUE(body.mechanism.empty());
    EXPECT_TRUE(body.parts.empty());
    // Every triangle once: the body's, the head's and the arm's boxes, 12 each. The head is
    // printed on the page, or on a floating layer when the search gives it one.
    std::size_t triangles = 0;
    for (const PrintedPart& p : printed)
        triangles += p.mesh.triangles.size();
    EXPECT_EQ(triangles, 36u);
    const auto on_arm = std::find_if(printed.begin(), printed.end(), [&](const PrintedPart& p) {
        return p.mechanism == arm.mechanisms.front();
    });
    ASSERT_NE(on_arm, printed.end());
    const PrintedPart& limb = *on_arm;
    EXPECT_EQ(body.mesh.triangles.size(), printed.size() == 2 ? 24u : 12u);
    EXPECT_EQ(limb.mechanism, arm.mechanisms.front());
    EXPECT_EQ(limb.parts, std::vector<std::string>{"M"});
    EXPECT_EQ(limb.chains, std::vector<std::string>{"arm"});
    ASSERT_EQ(limb.mesh.triangles.size(), 12u);
    Eigen::AlignedBox3d box;
    for (const Vec3& v : limb.mesh.vertices)
        box.extend(v);
    const Vec3 offset = r.value.targets.animation_to_card.topRightCorner<3, 1>();
    EXPECT_LT((box.min() - (arm_lo + offset)).norm(), 1e-6);
    EXPECT_LT((box.max() - (arm_hi + offset)).norm(), 1e-6);
    for (const Vec3& v : body.mesh.vertices) // no corner of the arm's box is in the body
        EXPECT_FALSE(
            v.x() > arm_lo.x() + offset.x() - 1e-9 && v.x() < arm_hi.x() + offset.x() + 1e-9 &&
            v.y() > arm_lo.y() + offset.y() - 1e-9 && v.y() < arm_hi.y() + offset.y() + 1e-9);
}

TEST(PrintedParts, WithoutAMeshThereIsNothingToPrint)
{
    Animation a = rig();
    const MotionOptions o = options_for(a);
    a.mesh = ModelMesh{};
    a.skin.clear();
    const Result<MotionResult> r = design_motion(a, o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(printed_parts(a, r.value).empty());
}

} // namespace popup::motion
