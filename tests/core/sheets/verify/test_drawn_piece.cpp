// Reading a drawing into pieces: what cannot be read is refused with its reason; a region without
// a label is an error, a bare scrap a warning.
// Through verify_sheets, on drawings edited by hand here: what it must find is known from the edit
// (a line moved by 0.5 mm is 0.5 mm off), never from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "popup/sheets/verify_sheets.hpp"
#include "sheet_designs.hpp"
#include "verify_fixtures.hpp"

using namespace popup;
using namespace popup::verify_fixtures;

TEST(VerifySheets, UnusableDrawingsAreRefusedWithTheirReason)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    auto refused = [&](SheetDrawing d, const std::string& says) {
        const Result<RoundTrip> r = verify_sheets(tent.design, {d});
        EXPECT_FALSE(r.ok) << says;
        ASSERT_FALSE(r.diagnostics.empty()) << says;
        EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::drawing_unusable);
        EXPECT_NE(r.diagnostics.front().message.find(says), std::string::npos)
            << r.diagnostics.front().message;
    };
    const SheetDrawing good = draw_sheets(tent.sheets).front();
    EXPECT_FALSE(verify_sheets(tent.design, {}).ok);
    SheetDrawing d = good;
    d.cut.clear();
    refused(d, "no loop on the CUT layer");
    d = good;
    d.cut.front()[0].x() = std::numeric_limits<double>::quiet_NaN();
    refused(d, "not finite");
    d = good;
    d.cut.front()[0].x() = 1e7;
    refused(d, "beyond ±1e6 mm");
    d = good;
    std::swap(d.cut.front()[0], d.cut.front()[1]); // a rectangle turned into a bow tie
    refused(d, "crosses itself");
    d = good;
    d.kerf = -1.0;
    refused(d, "kerf");
    d = good;
    d.folds.front().to = d.folds.front().from;
    refused(d, "has no length");
}

TEST(VerifySheets, ARegionWithoutLabelIsAnErrorAndABareScrapAWarning)
{
    const Laid tent = laid_out(fixtures::single_mechanism_cards().front().scaffold);
    std::vector<SheetDrawing> drawings = draw_sheets(tent.sheets);
    SheetDrawing& d = drawings.front();
    d.cut.push_back({{500, 500}, {501, 500}, {501, 501}}); // a 0.5 mm² scrap, bare
    Result<RoundTrip> r = verify_sheets(tent.design, drawings);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.ok); // a warning only
    d.labels.erase(std::remove_if(d.labels.begin(), d.labels.end(),
                                  [](const DrawnText& t) { return t.text == "P2"; }),
                   d.labels.end());
    r = verify_sheets(tent.design, drawings);
    EXPECT_FALSE(r.value.ok);
    EXPECT_FALSE(errors_with(r, DiagnosticCode::unlabelled_piece).empty());
    EXPECT_FALSE(errors_with(r, DiagnosticCode::missing_piece).empty());
}
