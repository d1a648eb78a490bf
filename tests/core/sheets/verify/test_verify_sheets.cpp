// verify_sheets end to end: a layout's own drawing verifies.
// Through verify_sheets, on drawings edited by hand here: what it must find is known from the edit
// (a line moved by 0.5 mm is 0.5 mm off), never from the code under test.
#include <gtest/gtest.h>

#include "popup/sheets/verify_sheets.hpp"
#include "sheet_designs.hpp"
#include "verify_fixtures.hpp"

using namespace popup;
using namespace popup::verify_fixtures;

TEST(VerifySheets, TheLayoutsOwnDrawingMatchesWithinTheTolerance)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    const Result<RoundTrip> r = verify_sheets(tent.design, draw_sheets(tent.sheets));
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.ok);
    EXPECT_EQ(r.value.angles, 13);
    EXPECT_NEAR(r.value.tolerance, 1e-6 * tent.design.size(), 1e-15);
    EXPECT_LE(r.value.max_error, r.value.tolerance);
}
