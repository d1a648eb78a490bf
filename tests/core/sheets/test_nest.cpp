// Paper sizes, true-shape nesting and the shelf-packing baseline (the cutting sheets, issue 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <polyclipping/clipper.hpp>
#include <string>
#include <tuple>

#include "nest_shapes_fixture.hpp"
#include "popup/sheets/nest.hpp"

using namespace popup;
using popup::fixtures::l_shape_loop;
using popup::fixtures::popup_piece_set;
using popup::fixtures::rectangle_loop;

namespace {

using Packer = std::function<Result<Nesting>(const std::vector<NestShape>&, const NestOptions&)>;

constexpr double kUnitsPerMm = 1e6;
constexpr double kTolerance = 1e-6; // mm

/// The shape's outer loop where the placement puts it on its sheet.
Loop2 placed_outline(const NestShape& shape, const Placement& placement)
{
    const double angle = placement.rotation_deg * 3.14159265358979323846 / 180.0;
    const Eigen::Rotation2Dd rotation(angle);
    Loop2 placed;
    for (const Vec2& p : shape.outer)
        placed.push_back(rotation * p + placement.translation);
    return placed;
}

ClipperLib::Path to_units(const Loop2& loop)
{
    ClipperLib::Path path;
    for (const Vec2& p : loop)
        path.push_back({std::llround(p.x() * kUnitsPerMm), std::llround(p.y() * kUnitsPerMm)});
    return path;
}

double intersection_area(const ClipperLib::Paths& a, const ClipperLib::Paths& b)
{
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptClip, true);
    ClipperLib::Paths common;
    clipper.Execute(ClipperLib::ctIntersection, common, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    double area = 0.0;
    for (const ClipperLib::Path& path : common)
        area += ClipperLib::Area(path);
    return std::abs(area) / (kUnitsPerMm * kUnitsPerMm);
}

/// The loop grown by `distance` mm with round corners: every point within that distance.
ClipperLib::Paths grown(const ClipperLib::Path& path, double distance)
{
    ClipperLib::ClipperOffset offset(2.0, 100.0); // arcs within 100 nm
    offset.AddPath(path, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    ClipperLib::Paths result;
    offset.Execute(result, distance * kUnitsPerMm);
    return result;
}

/// No two shapes on a sheet overlap or come closer than the spacing; all keep the margin.
void expect_valid_layout(const std::vector<NestShape>& shapes, const NestOptions& options,
                         const Nesting& nesting)
{
    ASSERT_EQ(nesting.placements.size(), shapes.size());
    std::vector<Loop2> placed;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Placement& placement = nesting.placements[i];
        EXPECT_GE(placement.sheet, 0);
        EXPECT_LT(placement.sheet, nesting.sheet_count);
        placed.push_back(placed_outline(shapes[i], placement));
        for (const Vec2& p : placed.back()) {
            EXPECT_GE(p.x(), options.margin - kTolerance) << shapes[i].name;
            EXPECT_GE(p.y(), options.margin - kTolerance) << shapes[i].name;
            EXPECT_LE(p.x(), options.paper.width - options.margin + kTolerance) << shapes[i].name;
            EXPECT_LE(p.y(), options.paper.height - options.margin + kTolerance) << shapes[i].name;
        }
    }
    // A gap of at least the spacing: the outlines grown by just under half of it stay apart.
    const double half_gap = 0.5 * options.spacing - kTolerance;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            if (nesting.placements[i].sheet != nesting.placements[j].sheet)
                continue;
            const ClipperLib::Path a = to_units(placed[i]);
            const ClipperLib::Path b = to_units(placed[j]);
            EXPECT_EQ(intersection_area({a}, {b}), 0.0) << shapes[i].name << " " << shapes[j].name;
            if (half_gap > 0.0) {
                EXPECT_EQ(intersection_area(grown(a, half_gap), grown(b, half_gap)), 0.0)
                    << shapes[i].name << " " << shapes[j].name;
            }
        }
    }
}

NestShape shape(std::string name, Loop2 outer)
{
    return {std::move(name), std::move(outer), {}};
}

NestOptions a4(double margin = 10.0, double spacing = 2.0)
{
    NestOptions options;
    options.margin = margin;
    options.spacing = spacing;
    return options;
}

void expect_error(const Result<Nesting>& result, const std::string& code,
                  const std::string& subject, const std::vector<std::string>& message_parts)
{
    ASSERT_FALSE(result.ok);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    const Diagnostic& diagnostic = result.diagnostics.front();
    EXPECT_EQ(to_string(diagnostic.code), code);
    EXPECT_NE(diagnostic.message.find(subject), std::string::npos) << diagnostic.message;
    for (const std::string& part : message_parts)
        EXPECT_NE(diagnostic.message.find(part), std::string::npos)
            << "\"" << part << "\" missing from: " << diagnostic.message;
}

const std::vector<std::pair<std::string, Packer>> kPackers{{"nest_shapes", nest_shapes},
                                                           {"shelf_pack", shelf_pack}};

} // namespace

TEST(PaperByName, PresetsIgnoreCase)
{
    const std::vector<std::tuple<std::string, std::string, double, double>> cases{
        {"A4", "A4", 210.0, 297.0},
        {"a3", "A3", 297.0, 420.0},
        {"LETTER", "Letter", 215.9, 279.4},
        {" tabloid ", "Tabloid", 279.4, 431.8}};
    for (const auto& [query, name, width, height] : cases) {
        const Result<Paper> paper = paper_by_name(query);
        ASSERT_TRUE(paper.ok) << query;
        EXPECT_EQ(paper.value.name, name);
        EXPECT_DOUBLE_EQ(paper.value.width, width);
        EXPECT_DOUBLE_EQ(paper.value.height, height);
    }
}

TEST(PaperByName, CustomSizesInMillimetres)
{
    const Result<Paper> landscape = paper_by_name("300x200");
    ASSERT_TRUE(landscape.ok);
    EXPECT_DOUBLE_EQ(landscape.value.width, 300.0);
    EXPECT_DOUBLE_EQ(landscape.value.height, 200.0);
    const Result<Paper> fractional = paper_by_name("300.5X200");
    ASSERT_TRUE(fractional.ok);
    EXPECT_DOUBLE_EQ(fractional.value.width, 300.5);
    EXPECT_DOUBLE_EQ(fractional.value.height, 200.0);
    EXPECT_TRUE(paper_by_name("1000x1000").ok);
}

TEST(PaperByName, UnknownOrOutOfRangeNamesTheAllowedValues)
{
    for (const std::string name : {"B5", "", "300x", "x200", "0x200", "-300x200", "1000.5x200",
                                   "300x200x100", "300,5x200", "nanx200"}) {
        const Result<Paper> paper = paper_by_name(name);
        ASSERT_FALSE(paper.ok) << name;
        ASSERT_EQ(paper.diagnostics.size(), 1u);
        const Diagnostic& diagnostic = paper.diagnostics.front();
        EXPECT_EQ(diagnostic.code, DiagnosticCode::bad_paper);
        EXPECT_EQ(diagnostic.parameter, "paper");
        for (const char* part : {"A4", "A3", "Letter", "Tabloid", "<width>x<height>", "1000 mm"})
            EXPECT_NE(diagnostic.message.find(part), std::string::npos) << diagnostic.message;
        EXPECT_NE(diagnostic.message.find("\"" + name + "\""), std::string::npos)
            << diagnostic.message;
    }
}

TEST(NestShapes, SyntheticSetKeepsSpacingAndMargins)
{
    const std::vector<NestShape> pieces = popup_piece_set();
    for (const NestOptions& options : {a4(), a4(5.0, 0.0), a4(12.5, 3.5)}) {
        const Result<Nesting> nesting = nest_shapes(pieces, options);
        ASSERT_TRUE(nesting.ok);
        SCOPED_TRACE("margin " + std::to_string(options.margin) + " spacing " +
                     std::to_string(options.spacing));
        expect_valid_layout(pieces, options, nesting.value);
    }
}

TEST(ShelfPack, SyntheticSetKeepsSpacingAndMargins)
{
    const std::vector<NestShape> pieces = popup_piece_set();
    for (const NestOptions& options : {a4(), a4(5.0, 0.0), a4(12.5, 3.5)}) {
        const Result<Nesting> nesting = shelf_pack(pieces, options);
        ASSERT_TRUE(nesting.ok);
        expect_valid_layout(pieces, options, nesting.value);
    }
}

TEST(NestShapes, UsesNoMoreSheetsThanShelfPack)
{
    const std::vector<NestShape> pieces = popup_piece_set();
    for (const NestOptions& options : {a4(), a4(5.0, 0.0)}) {
        const Result<Nesting> nested = nest_shapes(pieces, options);
        const Result<Nesting> shelved = shelf_pack(pieces, options);
        ASSERT_TRUE(nested.ok && shelved.ok);
        EXPECT_LE(nested.value.sheet_count, shelved.value.sheet_count);
        EXPECT_GE(nested.value.sheet_count, 4); // the set's area is 3.77 printable A4s
    }
    // The goal, on the default options: at most 0.8 times the shelf packer's sheets.
    const Result<Nesting> nested = nest_shapes(pieces, a4());
    const Result<Nesting> shelved = shelf_pack(pieces, a4());
    EXPECT_EQ(nested.value.sheet_count, 5);
    EXPECT_EQ(shelved.value.sheet_count, 7);
}

TEST(NestShapes, IsDeterministic)
{
    const std::vector<NestShape> pieces = popup_piece_set();
    const Result<Nesting> first = nest_shapes(pieces, a4());
    const Result<Nesting> second = nest_shapes(pieces, a4());
    ASSERT_TRUE(first.ok && second.ok);
    EXPECT_EQ(first.value.sheet_count, second.value.sheet_count);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        EXPECT_EQ(first.value.placements[i].sheet, second.value.placements[i].sheet);
        EXPECT_EQ(first.value.placements[i].rotation_deg, second.value.placements[i].rotation_deg);
        EXPECT_EQ(first.value.placements[i].translation, second.value.placements[i].translation);
    }
}

// The L's inner corner holds the square: one sheet, where bounding boxes need two.
TEST(NestShapes, SquareGoesIntoTheConcavityOfAnL)
{
    NestOptions options;
    options.paper = {"100x100", 100.0, 100.0};
    options.margin = 5.0;
    options.spacing = 2.0;
    const std::vector<NestShape> shapes{shape("piece L", l_shape_loop(90.0, 45.0)),
                                        shape("piece S", rectangle_loop(40.0, 40.0))};
    const Result<Nesting> nested = nest_shapes(shapes, options);
    ASSERT_TRUE(nested.ok);
    EXPECT_EQ(nested.value.sheet_count, 1);
    expect_valid_layout(shapes, options, nested.value);
    for (const Vec2& p : placed_outline(shapes[1], nested.value.placements[1])) {
        // Inside the L's bounding box but beyond both its arms.
        EXPECT_GE(std::min(p.x(), p.y()), 5.0 + 45.0 + 2.0 - kTolerance);
    }

    const Result<Nesting> shelved = shelf_pack(shapes, options);
    ASSERT_TRUE(shelved.ok);
    EXPECT_EQ(shelved.value.sheet_count, 2);
}

// The placement maps the shape's own coordinates, whatever their origin and winding.
TEST(NestShapes, PlacementMapsTheShapesOwnFrame)
{
    Loop2 clockwise = rectangle_loop(150.0, 60.0);
    std::reverse(clockwise.begin(), clockwise.end());
    for (Vec2& p : clockwise)
        p += Vec2(-500.0, 1234.5);
    const std::vector<NestShape> shapes{shape("piece far", clockwise),
                                        shape("piece near", rectangle_loop(30.0, 20.0))};
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        const Result<Nesting> nesting = pack(shapes, a4());
        ASSERT_TRUE(nesting.ok);
        EXPECT_EQ(nesting.value.sheet_count, 1);
        expect_valid_layout(shapes, a4(), nesting.value);
    }
}

// A shape exactly as large as the printable area fits; the next sheet takes the rest.
TEST(NestShapes, ExactFitFillsThePrintableArea)
{
    const std::vector<NestShape> shapes{shape("piece full", rectangle_loop(190.0, 277.0)),
                                        shape("piece wide", rectangle_loop(190.0, 20.0))};
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        const Result<Nesting> nesting = pack(shapes, a4());
        ASSERT_TRUE(nesting.ok);
        EXPECT_EQ(nesting.value.sheet_count, 2);
        EXPECT_NE(nesting.value.placements[0].sheet, nesting.value.placements[1].sheet);
        expect_valid_layout(shapes, a4(), nesting.value);
    }
}

// A piece wider than the printable area fits only turned: an error when turning is off.
TEST(NestShapes, RotateOffKeepsShapesUpright)
{
    const std::vector<NestShape> shapes{shape("piece long", rectangle_loop(250.0, 100.0)),
                                        shape("piece small", rectangle_loop(40.0, 30.0))};
    NestOptions options = a4();
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        options.rotate = true;
        const Result<Nesting> turned = pack(shapes, options);
        ASSERT_TRUE(turned.ok);
        EXPECT_EQ(std::fmod(turned.value.placements[0].rotation_deg, 180.0), 90.0);
        expect_valid_layout(shapes, options, turned.value);

        options.rotate = false;
        expect_error(pack(shapes, options), "piece_does_not_fit", "piece long",
                     {"piece long (250.0 x 100.0 mm) does not fit the printable area 190.0 x "
                      "277.0 mm of A4 with 10 mm margins",
                      "turning not allowed"});
        const Result<Nesting> upright = pack({shapes[1], shapes[1]}, options);
        ASSERT_TRUE(upright.ok);
        for (const Placement& placement : upright.value.placements)
            EXPECT_EQ(placement.rotation_deg, 0.0);
    }
}

TEST(NestShapes, TooBigShapeNamesItsSizeAndThePrintableArea)
{
    const std::vector<NestShape> shapes{shape("piece P1", rectangle_loop(50.0, 50.0)),
                                        shape("piece P3", rectangle_loop(250.0, 200.0))};
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        expect_error(pack(shapes, a4()), "piece_does_not_fit", "piece P3",
                     {"piece P3 (250.0 x 200.0 mm) does not fit the printable area 190.0 x 277.0 "
                      "mm of A4 with 10 mm margins"});
    }
}

TEST(NestShapes, DegenerateShapesAreErrors)
{
    const std::vector<NestShape> two_points{shape("piece P1", {{0.0, 0.0}, {10.0, 0.0}})};
    const std::vector<NestShape> flat{
        shape("piece P2", {{0.0, 0.0}, {10.0, 0.0}, {20.0, 0.0}, {5.0, 0.0}})};
    const std::vector<NestShape> unnamed{shape("", {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}})};
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        expect_error(pack(two_points, a4()), "bad_shape", "piece P1",
                     {"piece P1 has 2 outline points", "at least 3"});
        expect_error(pack(flat, a4()), "bad_shape", "piece P2", {"piece P2 has zero area"});
        expect_error(pack(unnamed, a4()), "bad_shape", "shape 0", {"shape 0 has zero area"});
    }
}

TEST(NestShapes, BadOptionsNameTheOptionAndItsRange)
{
    const std::vector<NestShape> shapes{shape("piece P1", rectangle_loop(50.0, 50.0))};
    NestOptions no_width = a4();
    no_width.paper.width = 0.0;
    NestOptions nan_height = a4();
    nan_height.paper.height = std::nan("");
    for (const auto& [name, pack] : kPackers) {
        SCOPED_TRACE(name);
        expect_error(pack(shapes, no_width), "bad_paper", "paper",
                     {"paper A4 is 0.0 x 297.0 mm", "greater than 0"});
        expect_error(pack(shapes, nan_height), "bad_paper", "paper", {"greater than 0"});
        expect_error(pack(shapes, a4(-1.0)), "bad_margin", "margin",
                     {"margin -1 mm", "at least 0 mm and less than 105 mm"});
        expect_error(pack(shapes, a4(105.0)), "bad_margin", "margin",
                     {"margin 105 mm leaves no printable area on A4 (210.0 x 297.0 mm)",
                      "less than 105 mm"});
        expect_error(pack(shapes, a4(10.0, -0.5)), "bad_spacing", "spacing",
                     {"spacing -0.5 mm", "at least 0 mm"});
    }
}

TEST(NestShapes, NoShapesNeedNoSheets)
{
    for (const auto& [name, pack] : kPackers) {
        const Result<Nesting> nesting = pack({}, a4());
        ASSERT_TRUE(nesting.ok) << name;
        EXPECT_EQ(nesting.value.sheet_count, 0) << name;
        EXPECT_TRUE(nesting.value.placements.empty()) << name;
    }
}

// Tall boxes lie down on the shelves: 20 x 90 strips turned give 22 mm shelves holding two each,
// so the third strip starts the second shelf 22 mm above the first.
TEST(ShelfPack, TurnsTallBoxesFlat)
{
    const std::vector<NestShape> strips(3, shape("strip", rectangle_loop(20.0, 90.0)));
    const Result<Nesting> nesting = shelf_pack(strips, a4());
    ASSERT_TRUE(nesting.ok);
    EXPECT_EQ(nesting.value.sheet_count, 1);
    const std::vector<double> shelf_bottoms{10.0, 10.0, 32.0};
    for (std::size_t i = 0; i < strips.size(); ++i) {
        EXPECT_EQ(nesting.value.placements[i].rotation_deg, 90.0);
        EXPECT_NEAR(nesting.value.placements[i].translation.y(), shelf_bottoms[i], kTolerance);
    }
    expect_valid_layout(strips, a4(), nesting.value);
}

/// Silhouette-like pieces: gears of 40 teeth, each splitting into far more convex parts than the
/// nesting's limit, so their grown hulls stand in. They still keep the spacing and the margins
/// (expect_valid_layout measures the exact outlines), and all six go on one A4 sheet: the hull of
/// a gear of outer radius 30 mm, grown by 1 mm, is within a 62 mm square.
TEST(NestShapes, WigglyOutlinesNestByTheirHullsWithoutOverlap)
{
    std::vector<NestShape> gears;
    for (int g = 0; g < 6; ++g) {
        Loop2 outer;
        for (int k = 0; k < 80; ++k) {
            const double a = 2 * M_PI * k / 80, r = k % 2 ? 24.0 : 30.0;
            outer.push_back({r * std::cos(a), r * std::sin(a)});
        }
        gears.push_back(shape("gear " + std::to_string(g), outer));
    }
    const NestOptions options = a4();
    const Result<Nesting> nesting = nest_shapes(gears, options);
    ASSERT_TRUE(nesting.ok);
    expect_valid_layout(gears, options, nesting.value);
    EXPECT_EQ(nesting.value.sheet_count, 1);
}
