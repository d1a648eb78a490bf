#pragma once
#include <cmath>

#include "motion/motion_mechanism.hpp"
#include "popup/model/card.hpp"

namespace popup::motion::testing {

/// The A4-sized card the samples below are drawn for: 210 × 148 mm.
inline CardParams a4_card()
{
    CardParams c;
    c.width = 210;
    c.depth = 148;
    return c;
}

/// The card PopUp makes for A4 sheets: 186 × 136.5 mm (open, it fills A4 inside the margins).
inline CardParams card_for_a4_sheets()
{
    CardParams c;
    c.width = 186;
    c.depth = 136.5;
    return c;
}

/// One feasible mechanism of each kind on an A4 card (210 × 148 mm), parameters chosen by hand.
inline MotionMechanism sample_mechanism(MotionKind kind)
{
    MotionMechanism m;
    m.kind = kind;
    switch (kind) {
    case MotionKind::rotation:
        m.p = {60, 40, 30, 25};
        break;
    case MotionKind::vertical:
        m.p = {80, 20, 30, 40 * M_PI / 180};
        break;
    case MotionKind::horizontal:
        m.p = {50, 30, 40, 15, 60};
        break;
    case MotionKind::diagonal:
        m.p = {70, 60, 50 * M_PI / 180, 50, 10, 12, 16, 12}; // glued creases: >= 11.1 mm
        break;
    case MotionKind::stationary:
        m.p = {40, 30, 20, 15, 10, 18};
        break;
    }
    return m;
}

/// A rotation off the central fold: the arm on the side pair of a floating layer whose supports
/// stand 30 mm from the fold (side +1: the ground's, −1: the backdrop's).
inline MotionMechanism off_fold_rotation(double side)
{
    MotionMechanism m;
    m.kind = MotionKind::rotation;
    m.p = {50, 40, 25, 30, side * 30};
    return m;
}

} // namespace popup::motion::testing
