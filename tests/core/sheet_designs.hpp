#pragma once
// Designs made with the mechanism generators, for the cutting-sheet tests and benchmarks.
#include <string>
#include <vector>

#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

struct NamedDesign {
    std::string name;
    Scaffold scaffold;
};

/// One card per mechanism type (and the diagonal translation: a step on a v-fold's wings).
std::vector<NamedDesign> single_mechanism_cards();

/// The `make demo` card: an A4 card (210 × 297 open) with a box carrying a tent, a floating
/// layer and a rotation arm on its top and a step on its side, a v-fold and a v-box beside it.
Scaffold demo_card();

/// A 240 × 240 mm card (open) with `boxes` boxes side by side, each carrying a tent and a floating
/// layer on its top and a step on each side: 1 + 13 × boxes pieces.
Scaffold many_piece_card(int boxes);

} // namespace popup::fixtures
