// The fold lines against the design's folds: place and layer.
// Through verify_sheets, on drawings edited by hand here: what it must find is known from the edit
// (a line moved by 0.5 mm is 0.5 mm off), never from the code under test.
#include <gtest/gtest.h>

#include "popup/sheets/verify_sheets.hpp"
#include "sheet_designs.hpp"
#include "verify_fixtures.hpp"

using namespace popup;
using namespace popup::verify_fixtures;

TEST(VerifySheets, AFoldMovedHalfAMillimetreIsNamedWithItsOffset)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    std::vector<SheetDrawing> drawings = draw_sheets(tent.sheets);
    DrawnFold& fold = drawings.front().folds.front();
    const Vec2 along = (fold.to - fold.from).normalized();
    const Vec2 across(-along.y(), along.x());
    fold.from += 0.5 * across;
    fold.to += 0.5 * across;
    const Result<RoundTrip> r = verify_sheets(tent.design, drawings);
    ASSERT_TRUE(r.ok);
    EXPECT_FALSE(r.value.ok);
    const auto moved = errors_with(r, DiagnosticCode::fold_misplaced);
    ASSERT_FALSE(moved.empty());
    EXPECT_NEAR(first_number_before_mm(moved.front().message), 0.5, 1e-3);
    EXPECT_EQ(moved.front().patches.size(), 2u);
    EXPECT_TRUE(errors_with(r, DiagnosticCode::outline_mismatch).empty());
}

TEST(VerifySheets, AFoldOnTheOtherLayerIsNamed)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    std::vector<SheetDrawing> drawings = draw_sheets(tent.sheets);
    for (DrawnFold& f : drawings.front().folds)
        f.direction = f.direction == FoldDirection::mountain ? FoldDirection::valley
                                                             : FoldDirection::mountain;
    const Result<RoundTrip> r = verify_sheets(tent.design, drawings);
    ASSERT_TRUE(r.ok);
    EXPECT_FALSE(r.value.ok);
    // Every fold and every tab crease of the card is on the wrong layer now.
    size_t lines = 0;
    for (const SheetPiece& piece : tent.sheets.pieces)
        lines += piece.folds.size();
    EXPECT_EQ(errors_with(r, DiagnosticCode::fold_direction_wrong).size(), lines);
}
