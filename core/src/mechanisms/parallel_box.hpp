#pragma once
// Internal: the parallel box section shared by the box fold and the floating layer: backbone C,
// sides L and R, top TG and TB (optionally overhanging the sides), end panels, and the pairs it
// offers (top, both sides).
#include "mechanism_builder.hpp"

namespace popup {

struct ParallelSection {
    double ground = 30.0;   ///< g: side L stands this far from the host hinge (mm)
    double backdrop = 30.0; ///< b (mm)
    double height = 30.0;   ///< c (mm)
    double overhang = 0.0;  ///< the top reaches this far beyond each side (mm)
    int panel_pairs = 1;    ///< end panel pairs per end, strips stacked up the end
    bool front = true;
    bool back = true;
};

/// Adds the section between y0 and y1 along the host hinge. Parameters are checked by callers.
void build_parallel_box(MechanismBuilder& m, double y0, double y1, const ParallelSection& s);

} // namespace popup
