// The mechanisms' pieces in closed form, against the card's reach across the fold.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "motion/mechanism_parts.hpp"
#include "motion/motion_feasibility.hpp"
#include "motion/reach_floor.hpp"
#include "motion_fixtures.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::motion {
namespace {

using testing::build;
using testing::Built;
using testing::sample_mechanism;
using testing::samples;

TEST(MechanismParts, EveryPatchStaysWithinTheCardsReachAcrossTheFold)
{
    // The premise of the reach floor (reach_floor.hpp): at fold angle θ no paper is seen farther
    // than depth·sin(θ/2) from the fold. The simulator's poses of every patch of each sample
    // design, pages included, at 37 angles (independent of the closed forms) ...
    const CardParams card = testing::a4_card();
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [kind, m] : samples()) {
        const Built b = build(m);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << kind;
        double worst = -1e9;
        for (const FoldState& state : sweep.value.states)
            for (std::size_t i = 0; i < b.scaffold.patches.size(); ++i)
                for (const Vec3& x : posed_outline(b.scaffold.patches[i], state.poses[i]))
                    worst = std::max(worst, std::abs(x.x()) - card_reach(card, state.angle));
        EXPECT_LE(worst, 1e-6) << kind;
        EXPECT_GT(worst, -1e-6) << kind << ": the pages' far edges reach it exactly";
    }
    // ... and the closed forms' pieces of random feasible mechanisms of every kind.
    std::mt19937_64 rng(11);
    std::normal_distribution<double> step(0.0, 1.0);
    for (int k = 0; k <= motion_kind_count + 1; ++k) {
        const MotionMechanism start =
            k < motion_kind_count ? sample_mechanism(MotionKind(k))
                                  : testing::off_fold_rotation(k == motion_kind_count ? 1 : -1);
        int tried = 0;
        double worst = -1e9;
        for (int trial = 0; trial < 3000; ++trial) {
            MotionMechanism m = start;
            for (int i = 0; i < parameter_count(m.kind()); ++i)
                parameter(m, i) +=
                    step(rng) *
                    (parameter_info(m.kind(), i).role == ParameterRole::angle ? 0.2 : 12.0);
            if (!feasible(m, card))
                continue;
            ++tried;
            for (double theta : angles)
                for (const Vec3& v : mechanism_vertices(m, theta))
                    worst = std::max(worst, std::abs(v.x()) - card_reach(card, theta));
        }
        EXPECT_GT(tried, 50) << k;
        EXPECT_LE(worst, 1e-6) << k; // the trilaterated corners round off by ~4e-7 mm
    }
}

} // namespace
} // namespace popup::motion
