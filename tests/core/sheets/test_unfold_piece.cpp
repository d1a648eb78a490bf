// Laying pieces flat (groundwork of the cutting sheets, issue 4).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/pieces.hpp"
#include "popup/sheets/unfold_piece.hpp"
#include "test_support.hpp"

using namespace popup;

namespace {
double area(const Loop2& loop)
{
    double a = 0.0;
    for (size_t i = 0; i < loop.size(); ++i) {
        const Vec2& p = loop[i];
        const Vec2& q = loop[(i + 1) % loop.size()];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * std::abs(a);
}

Eigen::AlignedBox2d bounds(const FlatPiece& flat)
{
    Eigen::AlignedBox2d box;
    for (const Loop2& loop : flat.outlines)
        for (const Vec2& x : loop)
            box.extend(x);
    return box;
}

// Every edge keeps its length: the patches are only moved, never stretched.
void expect_rigid(const Scaffold& s, const FlatPiece& flat)
{
    for (size_t k = 0; k < flat.patches.size(); ++k) {
        const Loop3& design = s.find_patch(flat.patches[k])->outer;
        const Loop2& laid = flat.outlines[k];
        ASSERT_EQ(design.size(), laid.size());
        for (size_t i = 0; i < design.size(); ++i) {
            const size_t j = (i + 1) % design.size();
            EXPECT_NEAR((laid[j] - laid[i]).norm(), (design[j] - design[i]).norm(), 1e-9);
        }
    }
}
} // namespace

TEST(UnfoldPiece, TentSlopesLieSideBySide)
{
    Scaffold s = fixtures::generator_card(240);
    TentFoldParams p;
    p.offset = 40;
    p.width = 60;
    p.foot = 30;
    p.foot_backdrop = 20;
    p.slope = 40; // backdrop slope 50
    const auto tent = add_tent_fold(s, central_fold(s), p);
    ASSERT_TRUE(tent.ok);
    const Result<FlatPiece> flat = unfold_piece(s, tent.value.patches);
    ASSERT_TRUE(flat.ok) << flat.diagnostics.front().message;
    expect_rigid(s, flat.value);
    const Eigen::AlignedBox2d box = bounds(flat.value);
    const Vec2 size = box.sizes();
    // 40 + 50 mm across the apex fold, 60 mm along it, whichever way the root frame turns.
    EXPECT_NEAR(std::max(size.x(), size.y()), 90.0, 1e-9);
    EXPECT_NEAR(std::min(size.x(), size.y()), 60.0, 1e-9);
    EXPECT_NEAR(area(flat.value.outlines[0]) + area(flat.value.outlines[1]), 90.0 * 60, 1e-6);
    ASSERT_EQ(flat.value.fold_lines.size(), 1u);
    EXPECT_NEAR((flat.value.fold_lines[0][1] - flat.value.fold_lines[0][0]).norm(), 60.0, 1e-9);
}

TEST(UnfoldPiece, BoxSectionBecomesOneStrip)
{
    Scaffold s = fixtures::generator_card(240);
    BoxFoldParams p;
    p.offset = 60;
    p.width = 80;
    p.depth_ground = p.depth_backdrop = 30;
    p.height = 25;
    const auto box = add_box_fold(s, central_fold(s), p);
    ASSERT_TRUE(box.ok);
    const auto& ids = box.value.patches; // C, L, R, TG, TB, ...
    // The strip L, TG, TB, R (C is a separate piece glued along the top crease).
    const Result<FlatPiece> flat =
        unfold_piece(s, std::vector<int>{ids[1], ids[3], ids[4], ids[2]});
    ASSERT_TRUE(flat.ok) << flat.diagnostics.front().message;
    expect_rigid(s, flat.value);
    const Vec2 size = bounds(flat.value).sizes();
    // L (25) + TG (30) + TB (30) + R (25) along the strip, 80 mm wide.
    EXPECT_NEAR(std::max(size.x(), size.y()), 110.0, 1e-9);
    EXPECT_NEAR(std::min(size.x(), size.y()), 80.0, 1e-9);
}

TEST(UnfoldPiece, ALoopThatCannotLieFlatIsNamed)
{
    // Ground, backdrop and a tent form a closed loop: cut from one sheet (every joint a fold
    // instead of the generator's glue tabs) the slopes would have to stretch: their apex edges
    // land 20 mm apart.
    Scaffold s = fixtures::generator_card(240);
    TentFoldParams p;
    p.offset = 40;
    p.width = 60;
    const auto tent = add_tent_fold(s, central_fold(s), p);
    ASSERT_TRUE(tent.ok);
    for (Hinge& h : s.hinges)
        h.kind = JointKind::fold;
    const Result<FlatPiece> flat = unfold_piece(
        s, std::vector<int>{s.ground, s.backdrop, tent.value.patches[0], tent.value.patches[1]});
    EXPECT_FALSE(flat.ok);
    EXPECT_EQ(flat.diagnostics.front().code, DiagnosticCode::not_developable);
    EXPECT_NE(flat.diagnostics.front().message.find("20 mm"), std::string::npos)
        << flat.diagnostics.front().message;
}

TEST(UnfoldPiece, DisconnectedPatchesAreNamed)
{
    Scaffold s = fixtures::generator_card(240);
    TentFoldParams p;
    p.offset = 40;
    p.width = 60;
    const auto tent = add_tent_fold(s, central_fold(s), p);
    const Result<FlatPiece> flat =
        unfold_piece(s, std::vector<int>{tent.value.patches[0], s.backdrop});
    EXPECT_FALSE(flat.ok);
    EXPECT_EQ(flat.diagnostics.front().code, DiagnosticCode::disconnected_piece);
    EXPECT_FALSE(unfold_piece(s, std::vector<int>{}).ok);
}

TEST(CutPieces, EveryMechanismIsMadeOfPiecesThatLieFlat)
{
    // The demo card's mechanisms and the motion mechanisms, each on a card of its own.
    struct Case {
        const char* name;
        size_t pieces; ///< including the card
        std::function<bool(Scaffold&)> add;
    };
    const std::vector<Case> cases{
        {"tent", 2,
         [](Scaffold& s) { return add_tent_fold(s, central_fold(s), TentFoldParams{}).ok; }},
        {"box", 5, // card, strip L-TG-TB-R, backbone C, front panels, back panels
         [](Scaffold& s) {
             BoxFoldParams p;
             p.offset = 60;
             p.width = 80;
             return add_box_fold(s, central_fold(s), p).ok;
         }},
        {"v-box", 2,
         [](Scaffold& s) {
             VBoxFoldParams p;
             p.offset = 60;
             return add_v_box_fold(s, central_fold(s), p).ok;
         }},
        {"horizontal translation", 3, // card, step, M
         [](Scaffold& s) {
             HorizontalTranslationParams p;
             p.offset = 60;
             return add_horizontal_translation(s, central_fold(s), p).ok;
         }},
        {"rotation arm", 3, // card, arm wing, backdrop wing glued on along the spine
         [](Scaffold& s) {
             RotationArmParams p;
             p.offset = 60;
             return add_rotation_arm(s, central_fold(s), p).ok;
         }},
    };
    for (const Case& c : cases) {
        Scaffold s = fixtures::generator_card(240);
        ASSERT_TRUE(c.add(s)) << c.name;
        const auto pieces = cut_pieces(s);
        EXPECT_EQ(pieces.size(), c.pieces) << c.name;
        EXPECT_EQ(pieces.front().front(), s.ground) << c.name;
        for (const auto& piece : pieces) {
            const Result<FlatPiece> flat = unfold_piece(s, piece);
            EXPECT_TRUE(flat.ok) << c.name << ": "
                                 << (flat.diagnostics.empty() ? "" : flat.diagnostics[0].message);
        }
    }
}
