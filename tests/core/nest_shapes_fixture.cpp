#include "nest_shapes_fixture.hpp"

#include <random>

namespace popup::fixtures {

namespace {

constexpr double kTabDepth = 8.0;

/// Uniform numbers from std::mt19937, whose sequence the standard fixes (the distributions it
/// leaves to the library, so they are not used).
class Numbers {
public:
    double between(double low, double high)
    {
        return low + (high - low) * static_cast<double>(engine_()) / 4294967296.0;
    }
    bool chance(double probability) { return between(0.0, 1.0) < probability; }

private:
    std::mt19937 engine_{20240611u};
};

/// `loop` with a trapezoid glue tab on each edge flagged in `tabbed` (edge i runs from point i
/// to point i + 1); the tab's sides lean in at 45° or less, and an inset tab leaves the edge's
/// ends free.
Loop2 with_tabs(const Loop2& loop, const std::vector<bool>& tabbed, bool inset)
{
    Loop2 result;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2& a = loop[i];
        const Vec2& b = loop[(i + 1) % loop.size()];
        result.push_back(a);
        if (!tabbed[i])
            continue;
        const double length = (b - a).norm();
        const Vec2 along = (b - a) / length;
        const Vec2 outward{along.y(), -along.x()}; // counter-clockwise: the inside is on the left
        const double end_gap = inset ? 0.1 * length : 0.0;
        const double lean = std::min(kTabDepth, 0.3 * (length - 2.0 * end_gap));
        const Vec2 foot_a = a + end_gap * along;
        const Vec2 foot_b = b - end_gap * along;
        if (inset)
            result.push_back(foot_a);
        result.push_back(foot_a + lean * along + kTabDepth * outward);
        result.push_back(foot_b - lean * along + kTabDepth * outward);
        if (inset)
            result.push_back(foot_b);
    }
    return result;
}

std::vector<bool> some_edges(Numbers& numbers, std::size_t edges, double probability)
{
    std::vector<bool> tabbed(edges);
    for (std::size_t i = 0; i < edges; ++i)
        tabbed[i] = numbers.chance(probability);
    return tabbed;
}

Loop2 panel(Numbers& numbers)
{
    const Loop2 base = rectangle_loop(numbers.between(30.0, 90.0), numbers.between(25.0, 70.0));
    return with_tabs(base, some_edges(numbers, 4, 0.4), numbers.chance(0.5));
}

Loop2 strip(Numbers& numbers)
{
    const Loop2 base = rectangle_loop(numbers.between(90.0, 170.0), numbers.between(12.0, 25.0));
    return with_tabs(base, {false, true, numbers.chance(0.3), true}, numbers.chance(0.5));
}

Loop2 l_shape(Numbers& numbers)
{
    const double size = numbers.between(50.0, 110.0);
    const Loop2 base = l_shape_loop(size, numbers.between(0.25, 0.45) * size);
    std::vector<bool> tabbed = some_edges(numbers, base.size(), 0.25);
    tabbed[2] = tabbed[3] = false; // tabs in the inner corner would cross each other
    return with_tabs(base, tabbed, false);
}

/// Two panels side by side along a fold, the right one lower (a step-fold piece).
Loop2 two_panels(Numbers& numbers)
{
    const double left_width = numbers.between(30.0, 70.0);
    const double right_width = numbers.between(30.0, 70.0);
    const double left_height = numbers.between(30.0, 80.0);
    const double right_height = numbers.between(0.4, 0.9) * left_height;
    const Loop2 base{{0.0, 0.0},
                     {left_width + right_width, 0.0},
                     {left_width + right_width, right_height},
                     {left_width, right_height},
                     {left_width, left_height},
                     {0.0, left_height}};
    return with_tabs(base, {false, false, true, false, numbers.chance(0.5), false}, true);
}

} // namespace

Loop2 rectangle_loop(double width, double height)
{
    return {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
}

Loop2 l_shape_loop(double size, double arm)
{
    return {{0.0, 0.0}, {size, 0.0}, {size, arm}, {arm, arm}, {arm, size}, {0.0, size}};
}

std::vector<NestShape> popup_piece_set(int count)
{
    Numbers numbers;
    std::vector<NestShape> pieces;
    for (int i = 0; i < count; ++i) {
        NestShape piece;
        piece.name = "piece P" + std::to_string(i + 1);
        if (i % 7 == 6) {
            piece.outer = pieces.back().outer;
        } else {
            switch (i % 4) {
            case 0:
                piece.outer = panel(numbers);
                break;
            case 1:
                piece.outer = strip(numbers);
                break;
            case 2:
                piece.outer = l_shape(numbers);
                break;
            default:
                piece.outer = two_panels(numbers);
            }
        }
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

} // namespace popup::fixtures
