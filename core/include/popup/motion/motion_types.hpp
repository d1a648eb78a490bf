#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/card.hpp"
#include "popup/model/option_field.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/model/stage_timings.hpp"
#include "popup/motion/motion_targets.hpp"

// The options and the result of design_motion, below its driver and its stages.

namespace popup {

/// What the maker chooses for an animated pop-up (thesis §6.2–6.4).
struct MotionOptions {
    MotionView view;
    ChainOptions chains;
    double motion_weight = 85.0;   ///< w_m of eq 6.5
    double depth_weight = 15.0;    ///< w_d of eq 6.5
    double collision_weight = 1e5; ///< w_c of eq 6.8
    long iterations = 4000;        ///< annealing iterations per search chain
    int search_chains = 2;         ///< independent annealing runs (one per core), best kept
    /// h_max (mm): the highest floating layer; <= 0: 25 mm on an A4 card, scaled to the card.
    double layer_height_max = 0.0;
    std::uint64_t seed = 1;
    bool outlines = true; ///< moving and stationary patches take the character's outline
    /// The chains to animate, by name as the report gives them (LinkageChain::name); every other
    /// chain is held still: its floating layer or its part printed on the page, never a moving
    /// mechanism. Empty: every chain is free to move. A name no chain has is a bad_option.
    std::vector<std::string> animate_only;
};

/// MotionOptions' fields (motion_options.cpp): its own first (motion_weight ... animate_only), then
/// the view's (group "view", motion_view_fields()) and the chains' (group "chains"); each with
/// its name, doc, unit, default (MotionOptions{}'s) and the range design_motion accepts. The
/// workbench builds `popup animate`'s flags and the From-animation panel from them.
const std::vector<OptionField>& motion_option_fields();

/// The ranges design_motion accepts (motion_option_fields(), check_motion_view, and the two
/// weights of eq 6.5 not both 0); one bad_option error per option outside them, naming it and
/// its range. The frame range against the animation is motion_targets' to check.
Diagnostics check_motion_options(const MotionOptions& options);

/// One chain of the result, as report.json lists it.
struct ChainReport {
    std::string name;
    std::string mapping; ///< "vertical", "diagonal", "horizontal", "rotation", "stationary"
    std::vector<std::string> mechanisms; ///< names of the mechanisms that carry it
    double error = 0.0;    ///< E_m (eq 6.6) divided by the character's diagonal on the card
    double error_mm = 0.0; ///< E_m in mm
    /// The lowest E_m any mechanism on the card could reach (the reach floor: the target beyond
    /// what the card shows across the fold while nearly closed), / the diagonal, and in mm
    double floor = 0.0;
    double floor_mm = 0.0;
    /// The best one mechanism does on this chain alone, collisions ignored: the lowest E_m of its
    /// own candidates (each kind fitted to its path) and of its part printed on the page, / the
    /// diagonal and in mm, and that mechanism's kind ("printed" for the page)
    double bound = 0.0;
    double bound_mm = 0.0;
    std::string bound_mechanism;
    double weight = 0.0;        ///< v_j
    std::string status;         ///< "animated", "merged" or "stationary"
    std::string reason;         ///< why merged or stationary; empty when animated as mapped
    std::vector<double> s;      ///< the samples of its path
    std::vector<Vec2> target;   ///< card (x, y) of the end effector at each s
    std::vector<Vec2> achieved; ///< card (x, y) of the mechanism's point at each s
};

struct MotionResult {
    CardParams card;
    MotionTargets targets;
    std::vector<FittedMechanism> mechanisms; ///< hosts before the mechanisms they carry
    std::vector<FittedProfile> profiles;
    std::vector<ChainReport> chains;
    Scaffold scaffold;           ///< card plus mechanisms at the design state (180°)
    bool valid = false;          ///< the simulator's full validity check passed on `scaffold`
    double weighted_error = 0.0; ///< Σ v_j E_m(j) / diagonal
    double weighted_floor = 0.0; ///< Σ v_j floor(j): no design on this card scores lower
    double weighted_bound = 0.0; ///< Σ v_j bound(j): each chain with its best mechanism alone
    long iterations = 0;         ///< annealing iterations run (all search chains)
    double cost = 0.0;           ///< eq 6.5 of the returned state
    StageTimings timings; ///< each stage's seconds, in order ("targets" first), and the call's
    Diagnostics diagnostics;

    /// `valid` with at least one mechanism on the card: when every chain is printed on the page
    /// nothing stands up, so no design is made of it and no sheets are cut.
    bool pops_up() const { return valid && !mechanisms.empty(); }
};

} // namespace popup
