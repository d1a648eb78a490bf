// The annealing (thesis Alg. 6.1) on hand-made chain paths: the incremental evaluation follows
// the full re-evaluation move for move, and a deep collision at the start is resolved.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/motion_annealing.hpp"
#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

using testing::Chain;
using testing::targets_of;

TEST(Annealing, IncrementalEvaluationFollowsTheFullReevaluation)
{
    // The cached per-mechanism errors and pairwise depths must give the same search as
    // recomputing everything: same seed, same accepted moves, same best state.
    const std::vector<Chain> chains = {{"a", rotation_mechanism(60, 40, 30, 25), 0.4},
                                       {"b", vertical_mechanism(80, 20, 30, 40 * M_PI / 180), 0.3},
                                       {"c", rotation_mechanism(75, 30, 20, 20), 0.3}};
    const MotionTargets t = targets_of(chains);
    AnnealProblem p;
    p.card.width = 210;
    p.card.depth = 148;
    p.diagonal = t.diagonal_mm;
    AnnealState start;
    for (std::size_t j = 0; j < chains.size(); ++j) {
        ChainTarget c;
        c.name = chains[j].name;
        c.s = t.paths[j].s;
        c.target = t.paths[j].effector;
        c.weight = chains[j].weight;
        p.chains.push_back(c);
        p.candidates.push_back(fit_candidates(c, p.card, 25));
        start.slots.push_back(
            {p.candidates.back()[int(chains[j].truth.kind())].mechanism, {int(j)}});
    }
    prepare_alike(p);
    AnnealOptions o;
    o.iterations = 1000;
    o.seed = 3;
    const AnnealResult fast = anneal(p, start, o);
    o.incremental = false;
    const AnnealResult full = anneal(p, start, o);
    EXPECT_EQ(fast.accepted, full.accepted);
    EXPECT_NEAR(fast.cost, full.cost, 1e-9);
    EXPECT_NEAR(fast.collision, full.collision, 1e-9);
    EXPECT_NEAR(fast.cost, state_cost(p, fast.best), 1e-9); // the cache matches a fresh sum
    EXPECT_NEAR(fast.collision, state_collision(p, fast.best), 1e-9);
}

TEST(Annealing, ADeepCollisionAtTheStartIsResolved)
{
    // Eight known mechanisms 25 mm apart along the fold (as in make bench) start 38 mm deep in
    // each other's room, far beyond where exp(w_c D_c) leaves the doubles (1.2 mm here). The
    // search must still tell deeper from shallower and leave with none; the depth is re-measured
    // from the returned state.
    AnnealProblem p;
    p.card.width = 210;
    p.card.depth = 148;
    p.diagonal = 180;
    AnnealState start;
    for (int i = 0; i < 8; ++i) {
        const double y = 5 + 25 * i;
        const MotionMechanism truth = i % 3 == 0 ? rotation_mechanism(y, 20, 15, 15)
                                      : i % 3 == 1
                                          ? vertical_mechanism(y + 10, 8, 20, 40 * M_PI / 180)
                                          : horizontal_mechanism(y, 14, 30, 10, 40.0 + 5.0 * i);
        ChainTarget t;
        t.name = "chain" + std::to_string(i);
        t.weight = 1.0 / 8;
        t.depth = std::min(1.0, mechanism_height(truth) / 25);
        for (int k = 0; k <= 30; ++k) {
            t.s.push_back(k / 30.0);
            t.target.push_back(mechanism_point(truth, M_PI * k / 30.0).head<2>());
        }
        p.chains.push_back(t);
        p.candidates.push_back(fit_candidates(t, p.card, 25));
        start.slots.push_back({p.candidates.back()[int(truth.kind())].mechanism, {i}});
    }
    prepare_alike(p);
    ASSERT_GT(state_collision(p, start), 20.0);
    AnnealOptions o;
    o.iterations = 2000;
    for (std::uint64_t seed : {1u, 2u}) {
        o.seed = seed;
        const AnnealResult r = anneal(p, start, o);
        EXPECT_EQ(r.collision, 0.0) << "seed " << seed;
        EXPECT_EQ(state_collision(p, r.best), 0.0) << "seed " << seed;
    }
}

} // namespace
} // namespace popup::motion
