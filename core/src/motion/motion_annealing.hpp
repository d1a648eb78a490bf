#pragma once
#include <atomic>
#include <cstdint>

#include "anneal_problem.hpp"
#include "popup/model/cancel_flag.hpp"

namespace popup::motion {

struct AnnealOptions {
    long iterations = 4000;
    std::uint64_t seed = 1;
    /// true: only the changed mechanism's error and volume are recomputed per move, and only
    /// its pairs tested; false: every mechanism and pair each move (the benchmark's baseline).
    bool incremental = true;
    const CancelFlag* cancel = nullptr;
    std::atomic<double>* progress = nullptr; ///< raised to progress_to over the run
    double progress_from = 0.0, progress_to = 1.0;
};

struct AnnealResult {
    AnnealState best;
    double cost = 0.0;      ///< eq 6.5 of best
    double collision = 0.0; ///< Σ D_c of best (0: collision-free)
    long iterations = 0;
    long accepted = 0;
};

/// Simulated annealing, Alg. 6.1: moves change a parameter 0.6, merge 0.2, translate 0.1, remap
/// 0.1 (remapping a single chain may also print it on the page, or lift a printed one back);
/// Gaussian steps 10° for angles, diagonal/20 for lengths, diagonal/50 for positions; T = 10·t0 (t0
/// the mean |ΔE| of 20 trial moves from the start) × 0.8 every 200 iterations; cost eq 6.5 + eq 6.8
/// until a collision-free state is reached, then collisions are refused. Deterministic for the
/// seed.
AnnealResult anneal(const AnnealProblem& problem, const AnnealState& start,
                    const AnnealOptions& options);

} // namespace popup::motion
