// The sheet set's JSON (docs/SHEET_FORMAT.md) written and read back: the numbers come back
// exactly, the text written again is the same, and a malformed document is refused naming its key
// path.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "popup/io/sheet_json.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "sheet_designs.hpp"

using namespace popup;

namespace {

SheetOptions a3()
{
    SheetOptions o;
    o.nest.paper = paper_by_name("A3").value;
    return o;
}

void expect_same_loop(const Loop2& a, const Loop2& b, const std::string& what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].x(), b[i].x()) << what << " point " << i;
        EXPECT_EQ(a[i].y(), b[i].y()) << what << " point " << i;
    }
}

void expect_same_regions(const std::vector<Region>& a, const std::vector<Region>& b,
                         const std::string& what)
{
    ASSERT_EQ(a.size(), b.size()) << what;
    for (size_t r = 0; r < a.size(); ++r) {
        expect_same_loop(a[r].outer, b[r].outer, what);
        ASSERT_EQ(a[r].holes.size(), b[r].holes.size()) << what;
        for (size_t h = 0; h < a[r].holes.size(); ++h)
            expect_same_loop(a[r].holes[h], b[r].holes[h], what + " hole");
    }
}

void expect_same_piece(const SheetPiece& a, const SheetPiece& b)
{
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.printed_side, b.printed_side) << a.id;
    EXPECT_EQ(a.sheet, b.sheet) << a.id;
    EXPECT_EQ(a.rotation, b.rotation) << a.id;
    ASSERT_EQ(a.patches.size(), b.patches.size()) << a.id;
    for (size_t k = 0; k < a.patches.size(); ++k) {
        const FlatPatch &x = a.patches[k], &y = b.patches[k];
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.name, y.name);
        expect_same_loop(x.outer, y.outer, a.id + " patch " + x.name);
        ASSERT_EQ(x.holes.size(), y.holes.size());
        EXPECT_TRUE(x.to_sheet == y.to_sheet) << a.id << " patch " << x.name;
    }
    expect_same_regions(a.cut, b.cut, a.id + " cut");
    expect_same_regions(a.cut_nominal, b.cut_nominal, a.id + " cut_nominal");
    ASSERT_EQ(a.folds.size(), b.folds.size()) << a.id;
    for (size_t k = 0; k < a.folds.size(); ++k) {
        EXPECT_EQ(a.folds[k].hinge, b.folds[k].hinge);
        EXPECT_TRUE(a.folds[k].from == b.folds[k].from && a.folds[k].to == b.folds[k].to);
        EXPECT_EQ(a.folds[k].direction, b.folds[k].direction);
        EXPECT_EQ(a.folds[k].kind, b.folds[k].kind);
    }
    ASSERT_EQ(a.tabs.size(), b.tabs.size()) << a.id;
    for (size_t k = 0; k < a.tabs.size(); ++k) {
        const GlueTab &x = a.tabs[k], &y = b.tabs[k];
        EXPECT_EQ(x.code, y.code);
        EXPECT_EQ(x.hinge, y.hinge);
        EXPECT_EQ(x.patch, y.patch);
        expect_same_loop(x.polygon, y.polygon, a.id + " tab " + x.code);
        EXPECT_EQ(x.width, y.width);
        EXPECT_EQ(x.target_piece, y.target_piece);
        EXPECT_EQ(x.target_patch, y.target_patch);
        EXPECT_EQ(x.front, y.front);
    }
    ASSERT_EQ(a.glue.size(), b.glue.size()) << a.id;
    for (size_t k = 0; k < a.glue.size(); ++k) {
        const GlueArea &x = a.glue[k], &y = b.glue[k];
        EXPECT_EQ(x.code, y.code);
        EXPECT_EQ(x.hinge, y.hinge);
        EXPECT_EQ(x.patch, y.patch);
        expect_same_loop(x.polygon, y.polygon, a.id + " glue " + x.code);
        EXPECT_EQ(x.tab_piece, y.tab_piece);
        EXPECT_EQ(x.front, y.front);
    }
    ASSERT_EQ(a.labels.size(), b.labels.size()) << a.id;
    for (size_t k = 0; k < a.labels.size(); ++k) {
        const SheetLabel &x = a.labels[k], &y = b.labels[k];
        EXPECT_EQ(x.text, y.text);
        EXPECT_EQ(x.kind, y.kind);
        EXPECT_TRUE(x.position == y.position) << a.id << " label " << x.text;
        EXPECT_EQ(x.height, y.height);
        EXPECT_EQ(x.angle, y.angle);
    }
}

// What the file records of a layout comes back exactly, number for number.
void expect_same_sheet_set(const SheetSet& a, const SheetSet& b)
{
    EXPECT_EQ(a.options.nest.paper.name, b.options.nest.paper.name);
    EXPECT_EQ(a.options.nest.paper.width, b.options.nest.paper.width);
    EXPECT_EQ(a.options.nest.paper.height, b.options.nest.paper.height);
    EXPECT_EQ(a.options.nest.margin, b.options.nest.margin);
    EXPECT_EQ(a.options.nest.spacing, b.options.nest.spacing);
    EXPECT_EQ(a.options.nest.rotate, b.options.nest.rotate);
    EXPECT_EQ(a.options.kerf, b.options.kerf);
    EXPECT_EQ(a.options.min_gap, b.options.min_gap);
    EXPECT_EQ(a.options.tab_width, b.options.tab_width);
    EXPECT_EQ(a.options.tab_angle, b.options.tab_angle);
    EXPECT_EQ(a.options.min_tab_width, b.options.min_tab_width);
    EXPECT_EQ(a.options.min_feature, b.options.min_feature);
    EXPECT_EQ(a.options.min_corner_angle, b.options.min_corner_angle);
    EXPECT_EQ(a.options.fold_hints, b.options.fold_hints);
    EXPECT_EQ(a.card_size, b.card_size);
    EXPECT_EQ(a.paper_thickness, b.paper_thickness);
    EXPECT_EQ(a.sheet_count, b.sheet_count);
    EXPECT_EQ(a.shelf_sheet_count, b.shelf_sheet_count);
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (size_t k = 0; k < a.pieces.size(); ++k)
        expect_same_piece(a.pieces[k], b.pieces[k]);
    ASSERT_EQ(a.assembly.size(), b.assembly.size());
    for (size_t k = 0; k < a.assembly.size(); ++k) {
        EXPECT_EQ(a.assembly[k].piece, b.assembly[k].piece);
        EXPECT_EQ(a.assembly[k].text, b.assembly[k].text);
        ASSERT_EQ(a.assembly[k].joins.size(), b.assembly[k].joins.size());
        for (size_t j = 0; j < a.assembly[k].joins.size(); ++j) {
            const AssemblyJoin &x = a.assembly[k].joins[j], &y = b.assembly[k].joins[j];
            EXPECT_EQ(x.code, y.code);
            EXPECT_EQ(x.tab_piece, y.tab_piece);
            EXPECT_EQ(x.target_piece, y.target_piece);
            EXPECT_EQ(x.front, y.front);
        }
    }
    EXPECT_EQ(a.cut_length, b.cut_length);
    EXPECT_EQ(a.stack_height, b.stack_height);
    EXPECT_EQ(a.round_trip.max_error, b.round_trip.max_error);
    EXPECT_EQ(a.round_trip.tolerance, b.round_trip.tolerance);
    EXPECT_EQ(a.round_trip.angles, b.round_trip.angles);
    EXPECT_EQ(a.round_trip.ok, b.round_trip.ok);
    ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size());
    for (size_t k = 0; k < a.diagnostics.size(); ++k) {
        const Diagnostic &x = a.diagnostics[k], &y = b.diagnostics[k];
        EXPECT_EQ(x.code, y.code);
        EXPECT_EQ(x.severity, y.severity);
        EXPECT_EQ(x.message, y.message);
        EXPECT_EQ(x.patches, y.patches);
        EXPECT_EQ(x.parameter, y.parameter);
        EXPECT_EQ(x.angle_deg, y.angle_deg);
    }
}

std::string read_text(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The error message of reading `document`, or "" when it reads.
std::string read_error(const nlohmann::json& document)
{
    const Result<SheetSet> r = sheet_set_from_json(document.dump());
    return r.ok ? "" : r.diagnostics.at(0).message;
}

} // namespace

TEST(SheetJson, ALayoutComesBackNumberForNumber)
{
    SheetOptions turned = a3();
    turned.printed_sides["P1"] = PrintedSide::back;
    turned.fold_hints = true;
    turned.kerf = 0.15;
    for (const SheetOptions& options : {a3(), turned}) {
        const Result<SheetSet> laid = layout_sheets(fixtures::demo_card(), options);
        ASSERT_TRUE(laid.ok);
        ASSERT_FALSE(laid.value.diagnostics.empty()); // the findings come back too
        const std::string text = sheet_set_to_json(laid.value);
        const Result<SheetSet> read = sheet_set_from_json(text);
        ASSERT_TRUE(read.ok) << read.diagnostics.at(0).message;
        expect_same_sheet_set(laid.value, read.value);
        EXPECT_EQ(sheet_set_to_json(read.value), text);
    }
}

TEST(SheetJson, AHandMadeFileTakesTheDefaultsOfWhatItLeavesOut)
{
    // The writers' fixture has no printed sides, frames (to_sheet) or join tab pieces.
    const std::string text = read_text("tests/data/sheet_set_sample.json");
    ASSERT_FALSE(text.empty());
    const Result<SheetSet> read = sheet_set_from_json(text);
    ASSERT_TRUE(read.ok) << read.diagnostics.at(0).message;
    const SheetSet& set = read.value;
    EXPECT_EQ(set.sheet_count, 2);
    ASSERT_EQ(set.pieces.size(), 4u);
    EXPECT_EQ(set.pieces[1].id, "P2");
    EXPECT_EQ(set.pieces[1].tabs[0].target_piece, 0);
    EXPECT_EQ(set.pieces[1].glue[0].tab_piece, 3);
    EXPECT_EQ(set.pieces[1].printed_side, PrintedSide::front);
    EXPECT_FALSE(set.pieces[0].patches[0].has_to_sheet());
    EXPECT_EQ(set.assembly[0].joins[0].tab_piece, 1); // the step's piece
    EXPECT_EQ(set.cut_length, 1532.54297244);
    EXPECT_EQ(set.options.min_gap, SheetOptions{}.min_gap);
    EXPECT_EQ(set.diagnostics.at(0).code, DiagnosticCode::narrow_tab);
    // Written again it keeps leaving the frames out, and reads back the same.
    const std::string again = sheet_set_to_json(set);
    EXPECT_EQ(nlohmann::json::parse(again)["pieces"][0]["patches"][0].count("to_sheet"), 0u);
    const Result<SheetSet> reread = sheet_set_from_json(again);
    ASSERT_TRUE(reread.ok);
    expect_same_sheet_set(set, reread.value);
    EXPECT_EQ(sheet_set_to_json(reread.value), again);
}

TEST(SheetJson, AMalformedDocumentIsRefusedNamingItsKeyPath)
{
    const nlohmann::json good =
        nlohmann::json::parse(read_text("tests/data/sheet_set_sample.json"));
    ASSERT_EQ(read_error(good), "");
    nlohmann::json bad = good;
    bad["pieces"][2].erase("cut");
    EXPECT_EQ(read_error(bad), "sheet set: pieces[2].cut missing");
    bad = good;
    bad["pieces"][0]["folds"][0]["direction"] = "up";
    EXPECT_EQ(read_error(bad),
              "sheet set: pieces[0].folds[0].direction is 'up', expected one of mountain, valley");
    bad = good;
    bad["sheets"][1]["pieces"].push_back("P9");
    EXPECT_EQ(read_error(bad), "sheet set: sheets[1].pieces[2] names unknown piece 'P9'");
    bad = good;
    bad["sheets"][1]["pieces"].push_back("P1");
    EXPECT_EQ(read_error(bad), "sheet set: sheets[1].pieces[2] places piece 'P1' a second time");
    bad = good;
    bad["pieces"][1]["tabs"][0]["target_piece"] = "P7";
    EXPECT_EQ(read_error(bad),
              "sheet set: pieces[1].tabs[0].target_piece names unknown piece 'P7'");
    bad = good;
    bad["version"] = 2;
    EXPECT_EQ(read_error(bad), "sheet set: version is 2, this reader knows 1");
    bad = good;
    bad["pieces"][0]["labels"][0]["height"] = 0;
    EXPECT_EQ(read_error(bad), "sheet set: pieces[0].labels[0].height must be positive, not 0");
    bad = good;
    bad["pieces"][0]["cut"][0]["outer"].erase(0);
    bad["pieces"][0]["cut"][0]["outer"].erase(0);
    EXPECT_EQ(read_error(bad),
              "sheet set: pieces[0].cut[0].outer has 2 points, a loop needs at least 3");
    bad = good;
    bad["pieces"][0]["patches"][0]["to_sheet"] = {{2, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(read_error(bad), "sheet set: pieces[0].patches[0].to_sheet is not a rotation or "
                               "reflection: determinant 2");
    bad = good;
    bad["diagnostics"][0]["code"] = "no_such_code";
    EXPECT_EQ(read_error(bad), "sheet set: diagnostics[0].code is 'no_such_code', not a code of "
                               "docs/DIAGNOSTICS.md");
    const Result<SheetSet> not_json = sheet_set_from_json("{\"format\": ");
    ASSERT_FALSE(not_json.ok);
    EXPECT_EQ(not_json.diagnostics.at(0).code, DiagnosticCode::bad_json);
    EXPECT_EQ(sheet_set_from_json(bad.dump()).diagnostics.at(0).parameter, "diagnostics[0].code");
}
