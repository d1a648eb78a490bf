#pragma once
// How the character sits on the card, the options of motion_targets (thesis ch. 6), with the
// table of their names, docs, units, defaults and ranges (motion_view.cpp).
#include <optional>
#include <vector>

#include "popup/geometry/vectors.hpp"
#include "popup/model/card.hpp"
#include "popup/model/option_field.hpp"

namespace popup {

/// How the character sits on the card (thesis ch. 6: the user's viewpoint and placement). The
/// card frame is the project's: y along the central fold, the card open flat in z = 0, ground
/// page x > 0. The viewer looks down from +z: the viewer's right (view × up) becomes +x, the
/// file's up +y. A character facing the eye has its own right hand at −x.
struct MotionView {
    Vec3 view = Vec3(0, 0, -1); ///< from the eye toward the character, in the file's axes
    Vec3 up = Vec3(0, 1, 0);    ///< the file's direction that becomes the card's +y
    /// Card mm per file unit; default: the projected bounding box (over the frame range) fits the
    /// card inside `margin`.
    std::optional<double> scale;
    /// Card (x, y) of the projected bounding box's centre; default (0, width / 2).
    std::optional<Vec2> centre;
    double margin = 0.1; ///< free border, fraction of each card dimension
    CardParams card;     ///< its width along the fold and each page's depth (mm)
    int first_frame = 0;
    int last_frame = -1;          ///< -1: the last
    double angle_tolerance = 2.0; ///< τangle (degrees) of the adaptive sampling (thesis §6.2)
    /// The adaptive sampling starts from this many equal intervals of s, so a straight path keeps
    /// samples along it and eq 6.6 sees its pace (adaptive_samples.hpp).
    int min_intervals = 8;
    /// false: a character (two chains or more) that travels along the ground (a walk) is kept in
    /// place, its root's travel across `up` taken out of every frame relative to the last, so
    /// its limbs' paths are what the card can show (docs/MATH.md, "A walk stays on the card").
    /// A single chain's travel is its motion and is always kept.
    bool keep_travel = false;
    /// With first_frame 0 and last_frame -1 (the whole take), show instead the frames a card can
    /// follow best (best_frame_window; docs/MATH.md, "The frame window").
    bool auto_frames = true;
};

/// MotionView's fields in declaration order (card_width and card_depth for its card): name, doc,
/// unit, default (MotionView{}'s) and range. The workbench builds `popup animate`'s flags and the
/// From-animation panel from them, through motion_option_fields (motion_types.hpp).
const std::vector<OptionField>& motion_view_fields();

/// The view's options on their own: their ranges (motion_view_fields()); view and up finite,
/// non-zero and across each other; scale > 0; centre finite; last_frame after first_frame unless
/// -1. The frame range against an animation's frames is motion_targets' to check. One bad_option
/// error per option, naming it and its range.
Diagnostics check_motion_view(const MotionView& view);

} // namespace popup
