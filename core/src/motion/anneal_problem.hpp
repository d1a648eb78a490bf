#pragma once
#include <array>
#include <vector>

#include "chain_mapping.hpp"
#include "collision_volume.hpp"

namespace popup::motion {

/// A mechanism of the design and the chains it carries (more than one once merged). A printed
/// slot has no mechanism: its chain's part is printed on the ground page (a still part that
/// takes no room from the moving mechanisms; `mechanism` is unused).
struct Slot {
    MotionMechanism mechanism;
    std::vector<int> chains;
    bool printed = false;
};

struct AnnealState {
    std::vector<Slot> slots;
};

/// What the search optimises over (thesis §6.4).
struct AnnealProblem {
    std::vector<ChainTarget> chains;
    std::vector<std::array<Candidate, motion_kind_count>> candidates; ///< per chain, per kind
    CardParams card;
    double diagonal = 1.0; ///< the character's diagonal on the card (mm): step sizes, E_m scale
    double h_max = 25.0;   ///< the tallest floating layer (mm): H of eq 6.7 is height / h_max
    double motion_weight = 85.0;
    double depth_weight = 15.0;
    double collision_weight = 1e5;
    VolumeOptions volumes;
    /// Chains whose motions (paths less their open-state points) stay this close (RMS, as a
    /// fraction of the diagonal) move alike and may share one mechanism (the merge move)...
    double alike_fraction = 0.05;
    /// ... when their parts also lie this close at the open state (a fraction of the diagonal):
    /// one patch carries both, each part at its own place on it.
    double beside_fraction = 0.1;
    /// still[j]: chain j does not move (mapped to the floating layer, Table 6.1): it takes its
    /// floating layer or the page only, never a moving mechanism (a flat one would dodge E_d and
    /// take room from the moving chains), and shares a patch with still chains only. Empty: none.
    std::vector<bool> still;
    /// alike[j][k]: chains j and k move alike (filled by prepare_alike).
    std::vector<std::vector<bool>> alike;
};

/// RMS distance (mm) between two chains' target paths, both interpolated linearly in s over the
/// union of their samples.
double path_distance(const ChainTarget& a, const ChainTarget& b);

/// RMS distance (mm) between two chains' motions: their target paths less their open-state
/// (s = 1) points, as path_distance. Two parts that move alike on one patch keep their places
/// on it: their paths differ by that constant offset only.
double motion_distance(const ChainTarget& a, const ChainTarget& b);

/// Fills problem.alike from motion_distance and alike_fraction, and the open-state distance and
/// beside_fraction.
void prepare_alike(AnnealProblem& problem);

/// The card (x, y) path of a part printed on the ground page at its open-state point: the page
/// point x from the fold projects to x·sin(θ/2) at θ = π s.
std::vector<Vec2> printed_path(const ChainTarget& t);

/// Where slot `slot` carries chain t at t's samples. A printed part follows printed_path. On a
/// merged translating patch (every kind but the rotation arm, whose patch turns) each part keeps
/// its open-state place, the mechanism's point plus the constant offset target(1) − point(π)
/// (exact at the open state, where the outline is placed; the patches stay nearly parallel to
/// the pages in between). A merged rotation arm turns each part rigidly with its arm's wing from
/// its open-state place (rotation_carried_point). Otherwise the mechanism's point.
std::vector<Vec2> carried_path(const Slot& slot, const ChainTarget& t);

/// Eq 6.6 of chain t on slot: the RMS distance (mm) of carried_path from the target.
double carried_error(const Slot& slot, const ChainTarget& t);

/// The collision volume of a slot (none for a printed one). A merged translating patch carries
/// each part at its offset from the mechanism's point: each band's box also covers itself moved
/// by those offsets (in the card plane), the room the widened patch takes.
CollisionVolume slot_volume(const AnnealProblem& problem, const Slot& slot);

/// Σ v_j over the chains slot s carries.
double chain_weight(const AnnealProblem& problem, const Slot& s);

/// Eq 6.6 of chain j printed on the page (the path its part follows with no mechanism).
double printed_error(const AnnealProblem& problem, int j);

/// Eq 6.5 of one slot: Σ over its chains v_j (w_m E_m(j)/diagonal + w_d |D_j − H|), E_d only
/// for mechanisms with a height (not the flat rotation arm and extruding patch); a printed part
/// has H = 0.
double slot_cost(const AnnealProblem& problem, const Slot& slot);

/// The motion part of eq 6.5 alone: Σ over the state's chains v_j E_m(j) / diagonal (the
/// report's weighted error on the search's samples; chains in no slot are not counted).
double state_motion_error(const AnnealProblem& problem, const AnnealState& state);

/// Eq 6.5 and Σ D_c of a whole state (the full evaluation).
double state_cost(const AnnealProblem& problem, const AnnealState& state);
double state_collision(const AnnealProblem& problem, const AnnealState& state);

/// Pairs of slots whose volumes overlap, with the depth (i < j).
struct SlotCollision {
    int a = 0, b = 0;
    double depth = 0.0;
};
std::vector<SlotCollision> state_collisions(const AnnealProblem& problem, const AnnealState& state);

} // namespace popup::motion
