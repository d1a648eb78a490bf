// Where glue codes are printed, checked by the reader's rule (drawn_piece.cpp): a code belongs
// to the smallest glue area its position lies in.
#include <gtest/gtest.h>

#include "geometry/polygon_2d.hpp"
#include "sheets/clipper_ops.hpp"
#include "sheets/sheet_labels.hpp"

namespace popup::sheets {
namespace {

// The glue areas whose codes neither the round trip could read (found on a capture's rotation
// arm, a 16.7 × 11.2 mm layer support): the end panel's tab area R on the support's back, and
// the arm wing's area U, a triangle, on its front, overlapping most of it.
LocalPiece crowded_support()
{
    LocalPiece piece;
    piece.flat.patches = {15};
    piece.flat.outlines = {
        {Vec2(142.49, 36.59), Vec2(125.79, 36.59), Vec2(125.79, 25.41), Vec2(142.49, 25.41)}};
    piece.flat.holes = {{}};
    piece.index_of[15] = 0;
    GlueArea r;
    r.code = "R";
    r.patch = 15;
    r.front = false;
    r.polygon = {Vec2(142.49, 36.59), Vec2(125.79, 36.59), Vec2(133.31, 29.08),
                 Vec2(134.98, 29.08)};
    GlueArea u;
    u.code = "U";
    u.patch = 15;
    u.polygon = {Vec2(139.35, 34.36), Vec2(129.93, 27.65), Vec2(131.29, 35.71),
                 Vec2(131.29, 35.71)};
    piece.glue = {r, u};
    return piece;
}

// The reader's rule: the smallest glue area holding the point.
int read_as(const LocalPiece& piece, const Vec2& q)
{
    int smallest = -1;
    for (size_t k = 0; k < piece.glue.size(); ++k)
        if (point_in_polygon(piece.glue[k].polygon, q) &&
            (smallest < 0 || std::abs(loop_area(piece.glue[k].polygon)) <
                                 std::abs(loop_area(piece.glue[size_t(smallest)].polygon))))
            smallest = int(k);
    return smallest;
}

TEST(SheetLabels, CrowdedGlueAreasEachGetACodeTheReaderGivesThem)
{
    LocalPiece piece = crowded_support();
    add_labels(piece, "P6", false);
    int glue_labels = 0;
    for (const SheetLabel& label : piece.labels) {
        if (label.kind != "glue")
            continue;
        ++glue_labels;
        const int own = label.text.rfind("R", 0) == 0 ? 0 : 1;
        EXPECT_EQ(read_as(piece, label.position), own)
            << label.text << " at (" << label.position.x() << ", " << label.position.y() << ")";
        EXPECT_GT(distance_to_boundary(piece.glue[size_t(own)].polygon, label.position), 0.05)
            << label.text << " sits on its area's edge";
    }
    EXPECT_EQ(glue_labels, 2);
}

TEST(SheetLabels, AGlueAreaClearOfOthersHasItsCodeInTheMiddle)
{
    LocalPiece piece = crowded_support();
    piece.glue.pop_back();
    add_labels(piece, "P6", false);
    for (const SheetLabel& label : piece.labels)
        if (label.kind == "glue") {
            EXPECT_NEAR(label.position.x(), (142.49 + 125.79 + 133.31 + 134.98) / 4, 1e-9);
            EXPECT_NEAR(label.position.y(), (36.59 * 2 + 29.08 * 2) / 4, 1e-9);
        }
}

} // namespace
} // namespace popup::sheets
