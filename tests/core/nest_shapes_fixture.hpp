#pragma once
// Flat pieces with known sizes for the nesting tests and benchmarks.
#include <vector>

#include "popup/sheets/nest.hpp"

namespace popup::fixtures {

/// The rectangle [0, width] x [0, height], counter-clockwise.
Loop2 rectangle_loop(double width, double height);

/// An L: the square [0, size]² without its upper-right corner [arm, size]², counter-clockwise.
Loop2 l_shape_loop(double size, double arm);

/// `count` pop-up-like pieces, the same for every call: panels and strips with trapezoid glue
/// tabs (8 mm deep) on some edges, L-shapes and two-panel step pieces, about 4 to 16 points each,
/// every seventh a copy of the one before (cards repeat supports). All fit A4 with 10 mm
/// margins. Named "piece P1", "piece P2", ...
std::vector<NestShape> popup_piece_set(int count = 50);

} // namespace popup::fixtures
