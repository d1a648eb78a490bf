// The cut outline against the design's.
// Through verify_sheets, on drawings edited by hand here: what it must find is known from the edit
// (a line moved by 0.5 mm is 0.5 mm off), never from the code under test.
#include <gtest/gtest.h>

#include <algorithm>

#include "popup/sheets/verify_sheets.hpp"
#include "sheet_designs.hpp"
#include "verify_fixtures.hpp"

using namespace popup;
using namespace popup::verify_fixtures;

TEST(VerifySheets, APieceScaledByOnePercentIsNamedByItsOutline)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    std::vector<SheetDrawing> drawings = draw_sheets(tent.sheets);
    SheetDrawing& d = drawings.front();
    // Everything scaled about one point: the card's 200 mm side grows by 2 mm.
    const Vec2 centre(100.0, 100.0);
    auto grow = [&](Vec2& p) { p = centre + 1.01 * (p - centre); };
    for (Loop2& loop : d.cut)
        std::for_each(loop.begin(), loop.end(), grow);
    for (Loop2& loop : d.glue)
        std::for_each(loop.begin(), loop.end(), grow);
    for (DrawnFold& f : d.folds) {
        grow(f.from);
        grow(f.to);
    }
    for (DrawnText& t : d.labels)
        grow(t.position);
    const Result<RoundTrip> r = verify_sheets(tent.design, drawings);
    ASSERT_TRUE(r.ok);
    EXPECT_FALSE(r.value.ok);
    const auto off = errors_with(r, DiagnosticCode::outline_mismatch);
    ASSERT_FALSE(off.empty());
    EXPECT_NE(off.front().message.find("P1"), std::string::npos);
    // Half the growth of the longest side, give or take the best fit's spread.
    EXPECT_GT(first_number_before_mm(off.front().message), 0.5);
    EXPECT_LT(first_number_before_mm(off.front().message), 2.5);
}
