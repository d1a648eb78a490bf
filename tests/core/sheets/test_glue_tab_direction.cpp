// A glue tab whose joint runs through the middle of the patch it is glued onto (a step fold's
// tread on a box side): the tab may lie on either side of the joint, and its crease folds the way
// of the side its glue area is on. The design is the one `popup fit` makes of a stepped block
// (box B1 on the central fold, a step on each of its sides, box B2 on its top); the tread of the
// step on B1's ground side meets B1.L at half its height, through its centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "../sheet_designs.hpp"
#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/sheet_drawing.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/sheets/verify_sheets.hpp"

using namespace popup;
using popup::fixtures::box;
using popup::fixtures::must;
using popup::fixtures::step;

namespace {

// The fit's parameters, to the last bit (popup fit of a stepped block, 186 × 136.5 mm card:
// /tmp/acc/stepped8/report.json): the sheets' directions used to hang on rounding noise. The
// step on the ground side has run_backdrop 19.84 mm on a box side 39.68 mm high, so its tread
// meets the side on its centre line. `backdrop_first` builds the backdrop side's step first, as
// the fit with eight mechanisms does (it names the steps in build order).
Scaffold stepped_block(bool backdrop_first)
{
    CardParams c;
    c.width = 186.0;
    c.depth = 136.5;
    Scaffold s = make_card(c).value;
    const MechanismParts b1 = must(add_box_fold(s, central_fold(s),
                                                box(63.239999999999995, 59.519999999999996,
                                                    19.840000000000003, 39.68000000000001),
                                                "B1"),
                                   "B1");
    const BasePatchPair &top = b1.offered[0], &side_ground = b1.offered[1],
                        &side_backdrop = b1.offered[2];
    const StepFoldParams on_backdrop =
        step(4.959999999999994, 49.60000000000001, 29.76, 24.800000000000004);
    const StepFoldParams on_ground =
        step(9.920000000000002, 39.68000000000001, 24.800000000000004, 19.840000000000003);
    if (backdrop_first) {
        must(add_step_fold(s, side_backdrop, on_backdrop, "S1"), "S1");
        must(add_step_fold(s, side_ground, on_ground, "S2"), "S2");
    } else {
        must(add_step_fold(s, side_ground, on_ground, "S1"), "S1");
        must(add_step_fold(s, side_backdrop, on_backdrop, "S2"), "S2");
    }
    BoxFoldParams b2 =
        box(19.840000000000003, 19.840000000000003, 11.904000000000002, 11.903999999999996);
    must(add_box_fold(s, top, b2, "B2"), "B2");
    return s;
}

const Patch& named(const Scaffold& s, const std::string& name)
{
    const auto p = std::find_if(s.patches.begin(), s.patches.end(),
                                [&](const Patch& q) { return q.name == name; });
    if (p == s.patches.end())
        throw std::runtime_error("no patch " + name);
    return *p;
}

std::vector<Diagnostic> errors_in(const Diagnostics& all)
{
    std::vector<Diagnostic> found;
    std::copy_if(all.begin(), all.end(), std::back_inserter(found),
                 [](const Diagnostic& d) { return d.severity == Severity::error; });
    return found;
}

std::string listed(const std::vector<Diagnostic>& errors)
{
    std::string text;
    for (const Diagnostic& d : errors)
        text += d.message + "\n";
    return text;
}

// p reflected across the line through a and b.
Vec2 mirrored(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 along = (b - a).normalized();
    const Vec2 foot = a + along * along.dot(p - a);
    return 2.0 * foot - p;
}

double distance_to(const Loop2& loop, const Loop2& other)
{
    if (loop.size() != other.size())
        return 1e300;
    double farthest = 0.0;
    for (size_t k = 0; k < loop.size(); ++k)
        farthest = std::max(farthest, (loop[k] - other[k]).norm());
    return farthest;
}

bool inside_convex(const Loop2& loop, const Vec2& p)
{
    bool left = false, right = false;
    for (size_t k = 0; k < loop.size(); ++k) {
        const Vec2 e = loop[(k + 1) % loop.size()] - loop[k], q = p - loop[k];
        const double cross = e.x() * q.y() - e.y() * q.x();
        left = left || cross > 0;
        right = right || cross < 0;
    }
    return !(left && right);
}

struct TreadTab {
    const GlueTab* tab = nullptr;
    const SheetPiece* carrier = nullptr;
    const GlueArea* area = nullptr;
    const SheetPiece* target = nullptr;
};

// The tab that glues the ground side's step tread onto B1.L, and its glue area.
TreadTab tread_tab(const Scaffold& s, const SheetSet& sheets, const std::string& tread)
{
    TreadTab found;
    for (const SheetPiece& piece : sheets.pieces)
        for (const GlueTab& t : piece.tabs)
            if (t.patch == named(s, tread).id && t.target_patch == named(s, "B1.L").id) {
                found.tab = &t;
                found.carrier = &piece;
            }
    if (!found.tab)
        return found;
    for (const SheetPiece& piece : sheets.pieces)
        for (const GlueArea& g : piece.glue)
            if (g.code == found.tab->code) {
                found.area = &g;
                found.target = &piece;
            }
    return found;
}

class SteppedBlock : public ::testing::TestWithParam<bool> {};

} // namespace

TEST_P(SteppedBlock, SheetsVerifyAndRoundTripAtEveryAngle)
{
    const Scaffold s = stepped_block(GetParam());
    const Result<SheetSet> laid = layout_sheets(s, SheetOptions{});
    ASSERT_TRUE(laid.ok) << listed(laid.diagnostics);
    EXPECT_TRUE(errors_in(laid.diagnostics).empty()) << listed(errors_in(laid.diagnostics));
    // The writer's own round trip: every one of the 13 asked angles re-made within 1e-6 × size.
    const RoundTrip& own = laid.value.round_trip;
    EXPECT_TRUE(own.ok);
    EXPECT_EQ(own.angles, 13);
    EXPECT_LE(own.max_error, 1e-6 * s.size() + 1e-12);

    // B1.TG carries B1.C's glue area on its back across its whole length and B2.C's on its
    // front in the middle: both centred on the same point. Their codes must not print there
    // on top of each other (the maker could read neither).
    for (const SheetPiece& piece : laid.value.pieces)
        for (size_t i = 0; i < piece.labels.size(); ++i)
            for (size_t j = i + 1; j < piece.labels.size(); ++j)
                if (piece.labels[i].kind == "glue" && piece.labels[j].kind == "glue") {
                    EXPECT_GT((piece.labels[i].position - piece.labels[j].position).norm(),
                              0.5 * (piece.labels[i].height + piece.labels[j].height))
                        << piece.id << ": " << piece.labels[i].text << " and "
                        << piece.labels[j].text;
                }

    VerifyOptions v;
    for (const SheetPiece& piece : laid.value.pieces)
        v.printed_sides[piece.id] = piece.printed_side;
    const Result<RoundTrip> checked = verify_sheets(s, draw_sheets(laid.value), v);
    ASSERT_TRUE(checked.ok) << listed(checked.diagnostics);
    EXPECT_TRUE(errors_in(checked.diagnostics).empty()) << listed(errors_in(checked.diagnostics));
    EXPECT_TRUE(checked.value.ok);
    EXPECT_EQ(checked.value.angles, 13);
    EXPECT_LE(checked.value.max_error, 1e-6 * s.size() + 1e-12);
}

// Moving the tread's glue area to the other side of its joint on B1.L (its mirror image across
// the crease line) turns the tab the other way: the same crease layer is then wrong, and the
// other layer is right.
TEST_P(SteppedBlock, TheTreadTabFoldsTheWayOfTheSideItsGlueAreaIsOn)
{
    const bool backdrop_first = GetParam();
    const Scaffold s = stepped_block(backdrop_first);
    const Result<SheetSet> laid = layout_sheets(s, SheetOptions{});
    ASSERT_TRUE(laid.ok);
    const std::string tread = backdrop_first ? "S2.tread" : "S1.tread";
    const TreadTab t = tread_tab(s, laid.value, tread);
    ASSERT_NE(t.tab, nullptr) << "no tab from " << tread << " onto B1.L";
    ASSERT_NE(t.area, nullptr);
    // The joint runs through B1.L's centre line (19.84 of its 39.68 mm), so the area has paper
    // on both sides of its crease.
    VerifyOptions v;
    for (const SheetPiece& piece : laid.value.pieces)
        v.printed_sides[piece.id] = piece.printed_side;

    std::vector<SheetDrawing> drawings = draw_sheets(laid.value);
    SheetDrawing& under = drawings[size_t(t.target->sheet)];
    const auto area =
        std::min_element(under.glue.begin(), under.glue.end(), [&](const Loop2& a, const Loop2& b) {
            return distance_to(a, t.area->polygon) < distance_to(b, t.area->polygon);
        });
    ASSERT_LT(distance_to(*area, t.area->polygon), 1e-6);
    const Vec2 a = t.area->polygon[0], b = t.area->polygon[1];
    for (DrawnText& label : under.labels) // the area's code, not the tab's (maybe on this sheet)
        if (inside_convex(*area, label.position))
            label.position = mirrored(label.position, a, b);
    for (Vec2& p : *area)
        p = mirrored(p, a, b);

    const Result<RoundTrip> moved = verify_sheets(s, drawings, v);
    ASSERT_TRUE(moved.ok);
    EXPECT_FALSE(moved.value.ok);
    const auto wrong = errors_in(moved.diagnostics);
    ASSERT_EQ(wrong.size(), 1u) << listed(wrong);
    EXPECT_EQ(wrong.front().code, DiagnosticCode::fold_direction_wrong);
    EXPECT_NE(wrong.front().message.find(tread), std::string::npos) << wrong.front().message;

    // The tab's crease on the other layer: right again.
    SheetDrawing& on = drawings[size_t(t.carrier->sheet)];
    const auto crease = std::min_element(
        on.folds.begin(), on.folds.end(), [&](const DrawnFold& f, const DrawnFold& g) {
            return (f.from - t.tab->polygon[0]).norm() + (f.to - t.tab->polygon[1]).norm() <
                   (g.from - t.tab->polygon[0]).norm() + (g.to - t.tab->polygon[1]).norm();
        });
    ASSERT_LT((crease->from - t.tab->polygon[0]).norm() + (crease->to - t.tab->polygon[1]).norm(),
              1e-6);
    crease->direction = crease->direction == FoldDirection::mountain ? FoldDirection::valley
                                                                     : FoldDirection::mountain;
    const Result<RoundTrip> turned = verify_sheets(s, drawings, v);
    ASSERT_TRUE(turned.ok);
    EXPECT_TRUE(errors_in(turned.diagnostics).empty()) << listed(errors_in(turned.diagnostics));
    EXPECT_TRUE(turned.value.ok);
    EXPECT_LE(turned.value.max_error, 1e-6 * s.size() + 1e-12);
}

INSTANTIATE_TEST_SUITE_P(GlueTabDirection, SteppedBlock, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return info.param ? "BackdropStepFirst" : "GroundStepFirst";
                         });
