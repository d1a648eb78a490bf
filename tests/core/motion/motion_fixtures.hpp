#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "motion/build_mechanism.hpp"
#include "motion/motion_kinematics.hpp"
#include "motion/motion_parameters.hpp"
#include "motion/parameter_table.hpp"
#include "popup/model/card.hpp"
#include "popup/motion/motion_targets.hpp"

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
    switch (kind) {
    case MotionKind::rotation:
        return rotation_mechanism(60, 40, 30, 25);
    case MotionKind::vertical:
        return vertical_mechanism(80, 20, 30, 40 * M_PI / 180);
    case MotionKind::horizontal:
        return horizontal_mechanism(50, 30, 40, 15, 60);
    case MotionKind::diagonal:
        // glued creases: >= 11.1 mm
        return diagonal_mechanism(70, 60, 50 * M_PI / 180, 50, 10, 12, 16, 12);
    case MotionKind::stationary:
        break;
    }
    return layer_mechanism(40, 30, 20, 15, 10, 18);
}

/// A rotation off the central fold: the arm on the side pair of a floating layer whose supports
/// stand 30 mm from the fold (side +1: the ground's, −1: the backdrop's).
inline MotionMechanism off_fold_rotation(double side)
{
    return rotation_mechanism(50, 40, 25, 30, side * 30);
}

/// A mechanism built on the A4 card's central fold with the library's generators, and the ids
/// of its patches.
struct Built {
    Scaffold scaffold;
    std::vector<int> patches;
};

inline Built build(const MotionMechanism& m)
{
    const CardParams card = a4_card();
    Built b;
    b.scaffold = make_card(card).value;
    std::vector<FittedMechanism> rows;
    auto parts = build_mechanism(b.scaffold, central_fold(b.scaffold), m, "M", rows);
    EXPECT_TRUE(parts.ok) << (parts.diagnostics.empty() ? "" : parts.diagnostics[0].message);
    for (const MechanismParts& part : parts.value)
        b.patches.insert(b.patches.end(), part.patches.begin(), part.patches.end());
    return b;
}

constexpr MotionKind all_kinds[] = {MotionKind::vertical, MotionKind::diagonal,
                                    MotionKind::horizontal, MotionKind::rotation,
                                    MotionKind::stationary};

/// Every kind's sample, and the rotation off the fold on either side of a floating layer.
inline std::vector<std::pair<std::string, MotionMechanism>> samples()
{
    std::vector<std::pair<std::string, MotionMechanism>> out;
    for (MotionKind kind : all_kinds)
        out.push_back({to_string(kind), sample_mechanism(kind)});
    out.push_back({"rotation on side_ground", off_fold_rotation(1)});
    out.push_back({"rotation on side_backdrop", off_fold_rotation(-1)});
    return out;
}

/// A hand-made chain: its path is the closed-form path of `truth`.
struct Chain {
    std::string name;
    MotionMechanism truth;
    double weight;
    double depth = -1.0; ///< D of eq 6.7; < 0: the truth's own height over h_max = 25 mm
};

/// Targets whose chains follow their truths' points at 31 samples, on a 150 mm diagonal.
inline MotionTargets targets_of(const std::vector<Chain>& chains)
{
    MotionTargets t;
    t.diagonal_mm = 150;
    for (const Chain& c : chains) {
        LinkageChain l;
        l.name = c.name;
        l.weight = c.weight;
        t.chains.push_back(l);
        ChainPath p;
        // A rig driven by the mechanism stands as tall as it (eq 6.7's D = H).
        p.depth = c.depth >= 0 ? c.depth : std::min(1.0, mechanism_height(c.truth) / 25.0);
        for (int k = 0; k <= 30; ++k) {
            const double s = k / 30.0;
            p.s.push_back(s);
            p.effector.push_back(mechanism_point(c.truth, M_PI * s).head<2>());
            p.root.push_back(Vec2(0, 0));
        }
        t.paths.push_back(p);
    }
    return t;
}

} // namespace popup::motion::testing
