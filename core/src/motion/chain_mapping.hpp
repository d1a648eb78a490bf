#pragma once
#include <array>
#include <string>
#include <vector>

#include "motion_mechanism.hpp"
#include "popup/geometry/pose.hpp"
#include "popup/model/card.hpp"

namespace popup::motion {

/// One chain's target as the design stages see it: fold angles θ = π s and card (x, y).
struct ChainTarget {
    std::string name;
    std::vector<double> s;
    std::vector<Vec2> target;
    double weight = 0.0; ///< v_j
    double depth = 0.0;  ///< D of eq 6.7 (0 deepest .. 1 nearest)
};

/// Eq 6.6: the RMS distance (mm) between the target and the mechanism's point over the samples.
double motion_error(const MotionMechanism& m, const ChainTarget& t);

/// The mechanism's point path in card (x, y) at the chain's samples.
std::vector<Vec2> achieved_path(const MotionMechanism& m, const std::vector<double>& s);

struct Candidate {
    MotionMechanism mechanism;
    double error_mm = 0.0; ///< eq 6.6; infinity when no feasible parameters were found
    std::string why;       ///< why infeasible, when it is
};

/// The most samples the candidates' fits evaluate per step (search_target).
constexpr std::size_t fit_samples_max = 256;

/// t with at most `most` of its samples for a fit to evaluate: every k-th (k the smallest that
/// keeps within `most`) and the last, so the adaptive samples' density along the path is kept.
/// t itself when it has no more. A long capture's chain has thousands of samples (4511 frames:
/// ~8000) that a polish need not see one by one.
ChainTarget search_target(const ChainTarget& t, std::size_t most = fit_samples_max);

/// One candidate per MotionKind (index = the enum's value): initial parameters from the key
/// poses (closed forms at s = 0 and s = 1; for the rotation the 1-D search for the spine l of
/// eq 6.2, for the horizontal translation the 1-D search of the runs' ratio), then a bounded
/// Nelder–Mead polish of eq 6.6 inside the generators' ranges. The stationary candidate's
/// platform height is h_max·D (eq 6.7). The starts and the polish see search_target(t,
/// fit_samples); each candidate's error_mm is eq 6.6 over all of t's samples.
std::array<Candidate, motion_kind_count> fit_candidates(const ChainTarget& t,
                                                        const CardParams& card, double h_max,
                                                        std::size_t fit_samples = fit_samples_max);

/// fit_candidates' candidate of one kind alone (the same), so that the kinds of a character's
/// chains can be fitted side by side on threads (map_chains).
Candidate fit_candidate(MotionKind kind, const ChainTarget& t, const CardParams& card, double h_max,
                        std::size_t fit_samples = fit_samples_max);

/// Two candidates whose eq 6.6 errors differ by less than this fraction of the character's
/// diagonal make the path equally well: the mapping takes the one with fewer parameters.
constexpr double mapping_tie_fraction = 1e-4;

/// The candidate with the lowest eq 6.6 error (Table 6.1's mapping by error, thesis §6.2), the
/// one with fewer parameters among ties (mapping_tie_fraction of `diagonal`, mm); a chain whose
/// path stays within `still_mm` of its mean maps to the floating layer; when that does not fit,
/// to the best moving candidate if it is within `still_mm` of the path, else still to the layer
/// (its error infinite: the chain is left off the card's mechanisms).
MotionKind best_mapping(const std::array<Candidate, motion_kind_count>& candidates,
                        const ChainTarget& t, double still_mm, double diagonal);

} // namespace popup::motion
