#pragma once
// Internal: the paper an outline keeps so that a part stays on a fold or slit its silhouette
// leaves entirely (fit_outlines): a bridge from the fold to the nearest point of the outline.
#include <polyclipping/clipper.hpp>

#include "popup/model/profile.hpp"
#include "popup/model/scaffold.hpp"

namespace popup::fold_bridges {

/// For every fold, glued joint and slit of `patch` that the outline `shape` (Clipper paths in
/// `frame`, the patch's profile frame) meets along less than `smallest` mm, the narrowest
/// the sheets cut (touching it at a corner, or not at all), a bridge of paper from it to the
/// outline's nearest point: `width` mm wide along the fold (or the fold's whole length when
/// shorter), centred as near that point as the fold allows and run to the fold's end where it
/// would leave less than `smallest` of it, reaching 1 mm outward over the fold
/// so that clipping to the patch leaves its edge exactly on it, and a little into the outline.
/// A glued joint's bridge is also `tab_depth` deep along the joint, so a glue tab lands on it.
/// `paper` is the patch's paper in `frame` (which side of a fold is the patch). Paths in
/// `frame`; empty when the outline meets every fold and slit.
ClipperLib::Paths bridges(const Scaffold& s, int patch, const ProfileFrame& frame,
                          const ClipperLib::Paths& paper, const ClipperLib::Paths& shape,
                          double width, double tab_depth, double smallest);

} // namespace popup::fold_bridges
