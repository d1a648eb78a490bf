// The faces on either side of a drawn fold, found in the bridges a slot leaves.
// Through verify_sheets, on drawings edited by hand here: what it must find is known from the edit
// (a line moved by 0.5 mm is 0.5 mm off), never from the code under test.
#include <gtest/gtest.h>

#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/verify_sheets.hpp"
#include "verify_fixtures.hpp"

using namespace popup;
using namespace popup::verify_fixtures;

TEST(VerifySheets, AFoldCutBySlotsAlmostEndToEndIsFoundInItsBridges)
{
    // The extruding patch passes a slot cut along the riser–tread fold, leaving bridges of about
    // 5 mm at its ends: from a 56 mm patch on, none of the fold's 0.1/0.3/0.5/0.7/0.9 points was on
    // paper and the verifier reported the fold missing (found on a BVH from elsewhere). Any width
    // must verify.
    for (double width : {30.0, 50.0, 56.0, 82.6, 120.0}) {
        CardParams card;
        card.width = 210;
        card.depth = 148;
        Scaffold s = make_card(card).value;
        HorizontalTranslationParams p;
        p.offset = 20;
        p.width = width;
        ASSERT_TRUE(add_horizontal_translation(s, central_fold(s), p).ok) << width;
        const Laid laid = laid_out(s);
        const Result<RoundTrip> r = verify_sheets(laid.design, draw_sheets(laid.sheets));
        ASSERT_TRUE(r.ok) << width;
        EXPECT_TRUE(r.value.ok) << width;
        EXPECT_EQ(r.value.angles, 13) << width;
        EXPECT_TRUE(errors_with(r, DiagnosticCode::fold_missing).empty()) << width;
        EXPECT_TRUE(errors_with(r, DiagnosticCode::fold_extra).empty()) << width;
    }
}
