#pragma once
// Designs made with the mechanism generators, for the cutting-sheet tests and benchmarks.
#include <string>
#include <vector>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

/// A generator's parts, or an exception naming `what` (a fixture that fails is a broken test).
MechanismParts must(Result<MechanismParts> r, const std::string& what);

/// A box fold's parameters, the same depth on both pages.
BoxFoldParams box(double offset, double width, double depth, double height);

/// A step fold's parameters.
StepFoldParams step(double offset, double width, double run_ground, double run_backdrop);

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
