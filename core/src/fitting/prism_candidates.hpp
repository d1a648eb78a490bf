#pragma once
// Internal: candidate generation of the primitive search: one localised minimal sample makes a
// rectangular prism (two points) and, on a flat host, a triangular one (four points); each is
// fitted to its host, grown along the hinge and scored (thesis Fig 5.4).
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "localised_sampling.hpp"
#include "popup/fitting/prism_types.hpp"
#include "prism_faces.hpp"
#include "prism_scoring.hpp"

namespace popup::prism_search {

/// Feet and apex from the two slope lines; false unless they make a prism standing on the host.
bool triangle_from_lines(const PrismHost& h, Vec2 p1, Vec2 d1, Vec2 p2, Vec2 d2, double eps,
                         Prism& m);

/// One round of the search (it finds one prism): the samples no prism explains yet, and what
/// its draws score against.
struct Round {
    std::vector<int> remaining; ///< samples no prism explains, not on a host's plane
    /// Those of `remaining` on the outer surface: a draw starts at one (an inner sample, a
    /// box's top under its roof, may carry a face but no prism needs to explain it).
    std::vector<int> starts;
    double N = 0.0;     ///< how many starts
    double scale = 1.0; ///< remaining samples per sample of the scoring subset
    /// Gap allowed along the hinge between samples of one face: a few sample spacings of the
    /// scoring subset.
    double gap = 0.0;
    /// A draw picks its host among those its first sample stands on: at most this many.
    int hosts_per_sample = 1;
    /// Per host, the scoring subset and the guard above it in its coordinates, sorted along
    /// the hinge.
    std::vector<std::vector<Local>> sub, grd;
    /// Per host, the samples of `sub` that may lie on a rectangular or a triangular prism's
    /// face or stop its growth (may_carry_box, may_carry_slope), sorted along the hinge: all
    /// a candidate's growth and score read of the subset.
    std::vector<std::vector<Local>> box_sub, tent_sub;
};

/// What a draw reads besides the round: the hosts, every sample in each host's coordinates,
/// the accepted prisms' boxes and the samples' bounding box (card frame).
struct DrawInputs {
    const std::vector<PrismHost>& hosts;
    const std::vector<std::vector<Local>>& locals;
    const Search& search;
    const Cells& cells;
    const std::vector<Eigen::AlignedBox3d>& taken;
    const Eigen::AlignedBox3d& model;
    double eps = 0.0;
    double min_part = 0.0;
};

/// The best candidate of each kind a round's draws made, and how many minimal samples each
/// kind was drawn from.
struct Candidates {
    Scored best_rect, best_tri;
    long draws = 0, tri_draws = 0;
};

/// One localised minimal sample: its four points and the host they are read in (-1: none).
struct Draw {
    int p1 = 0, p2 = 0, p3 = 0, p4 = 0;
    int host = -1;
};

/// Draws a minimal sample: its first point, a cell level, three more points in that cell and a
/// host among those the first stands on, in this order.
Draw draw_sample(const Round& round, const DrawInputs& in, std::mt19937_64& rng,
                 std::uniform_int_distribution<size_t>& pick_point,
                 std::uniform_int_distribution<int>& pick_level);

/// The candidates a minimal sample makes replace the best of their kind in `found` when they
/// score higher and are accepted. Reads nothing else of `found` but the best scores: the
/// candidates of several samples may be tried apart, from the same `found`, then kept in
/// order by keep_better.
void try_candidates(const Draw& d, const Round& round, const DrawInputs& in, Candidates& found);

/// Each kind's best of `later` (tried after `found`'s) when it scores higher: the same best
/// as trying its samples after `found`'s own.
void keep_better(Candidates& found, const Candidates& later);

/// draw_sample, then try_candidates.
void draw_candidates(const Round& round, const DrawInputs& in, std::mt19937_64& rng,
                     std::uniform_int_distribution<size_t>& pick_point,
                     std::uniform_int_distribution<int>& pick_level, Candidates& found);

} // namespace popup::prism_search
