// The convex parts the nesting sums (sheets/nest/convex_parts.hpp): merging with the pairs found
// apart remembered gives the parts of testing every pair after every merge.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sheets/nest/convex_parts.hpp"

using namespace popup::nest_detail;
using ClipperLib::IntPoint;
using ClipperLib::Path;

namespace {

/// The merging as it was first written: every pair tested again after each merge.
void merge_testing_every_pair(std::vector<Path>& parts)
{
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < parts.size() && !merged; ++i) {
            for (std::size_t j = i + 1; j < parts.size() && !merged; ++j) {
                Path both = parts[i];
                both.insert(both.end(), parts[j].begin(), parts[j].end());
                Path hull = convex_hull(std::move(both));
                const double added = ClipperLib::Area(hull) - ClipperLib::Area(parts[i]) -
                                     ClipperLib::Area(parts[j]);
                if (added <= hull_slack(hull)) {
                    parts[i] = std::move(hull);
                    parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(j));
                    merged = true;
                }
            }
        }
    }
}

/// The trapezoids of `outline`'s horizontal slabs, as convex_parts cuts them before merging.
std::vector<Path> slab_pieces(const Path& outline)
{
    std::vector<ClipperLib::cInt> levels;
    for (const IntPoint& p : outline)
        levels.push_back(p.Y);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    const Bounds box = bounds_of(outline);
    std::vector<Path> parts;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        ClipperLib::Clipper clipper;
        clipper.StrictlySimple(true);
        clipper.AddPath(outline, ClipperLib::ptSubject, true);
        clipper.AddPath({{box.left, levels[k]},
                         {box.right, levels[k]},
                         {box.right, levels[k + 1]},
                         {box.left, levels[k + 1]}},
                        ClipperLib::ptClip, true);
        ClipperLib::Paths slab;
        clipper.Execute(ClipperLib::ctIntersection, slab, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        for (const Path& piece : slab)
            parts.push_back(convex_hull(piece));
    }
    return parts;
}

/// A star-like outline: `corners` points around a circle, their radii random in [0.6, 1] x 30 mm.
Path wiggly_outline(int corners, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> radius(0.6, 1.0);
    Path outline;
    for (int k = 0; k < corners; ++k) {
        const double a = 2 * M_PI * k / corners, r = 30e6 * radius(random);
        outline.push_back({static_cast<ClipperLib::cInt>(std::llround(r * std::cos(a))),
                           static_cast<ClipperLib::cInt>(std::llround(r * std::sin(a)))});
    }
    return outline;
}

} // namespace

TEST(ConvexParts, RememberedPairsMergeAsTestingEveryPairDoes)
{
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const std::vector<Path> pieces = slab_pieces(wiggly_outline(30 + 10 * int(seed), seed));
        ASSERT_GT(pieces.size(), 20u);
        std::vector<Path> remembered = pieces, every_pair = pieces;
        merge_while_hull_adds_nothing(remembered);
        merge_testing_every_pair(every_pair);
        EXPECT_EQ(remembered, every_pair) << "seed " << seed;
        EXPECT_LT(remembered.size(), pieces.size()) << "seed " << seed;
    }
}

TEST(ConvexParts, AnLIsTwoPartsAndNoPartsStayNone)
{
    constexpr ClipperLib::cInt mm = 1000000;
    const Path l{
        {0, 0},      {20 * mm, 0}, {20 * mm, 10 * mm}, {10 * mm, 10 * mm}, {10 * mm, 30 * mm},
        {0, 30 * mm}};
    EXPECT_EQ(convex_parts(l).size(), 2u);
    std::vector<Path> none;
    merge_while_hull_adds_nothing(none);
    EXPECT_TRUE(none.empty());
}
