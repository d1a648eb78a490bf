#pragma once
// Internal: what an outline must leave of a part's glued joints for the sheets to glue them
// (fit_outlines): the two rules that check it, and the strips of paper that keep it.
#include <map>
#include <set>
#include <string>

#include <polyclipping/clipper.hpp>

#include "popup/model/profile.hpp"
#include "popup/model/scaffold.hpp"

namespace popup::glued_joints {

/// Length of the shortest piece of each glued joint of `patch` (an outline may split one into
/// several, each carrying a tab of its own on the sheets), by the other patch's name.
std::map<std::string, double> joint_lengths(const Scaffold& s, int patch);

/// Glued joints of `patch` (by the other patch's name) along which the patch does not reach
/// `depth` inward over the joint's whole length: no tab that deep can be glued onto it there.
std::set<std::string> joints_without_room(const Scaffold& s, int patch, double depth);

/// The paper an outline keeps along the glued joints of `patch` so that each stays gluable:
/// for every stretch of a joint the outline `shape` (Clipper paths in `frame`, the patch's
/// profile frame) still meets, a strip `depth` deep inward over that stretch, lengthened about
/// its middle to `crease` (or the whole joint when shorter) where it is shorter. Stretches the
/// outline leaves get no strip: paper there would stand where the model has nothing. Each
/// strip also reaches 1 mm outward over the joint, so clipping to the patch leaves its edge
/// exactly on the joint. Paths in `frame`, one rectangle a strip.
ClipperLib::Paths joint_strips(const Scaffold& s, int patch, const ProfileFrame& frame,
                               const ClipperLib::Paths& shape, double crease, double depth);

} // namespace popup::glued_joints
