// map_chains fits the chains' candidates side by side on threads: what it finds is what
// fit_candidates finds for each chain alone, to the bit, and a cancel still stops it.
#include <gtest/gtest.h>

#include <atomic>

#include "motion/chain_mapping.hpp"
#include "motion/map_chains.hpp"
#include "motion/parameter_table.hpp"
#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

MotionTargets every_sample_mechanism()
{
    std::vector<testing::Chain> chains;
    for (const auto& [name, m] : testing::samples())
        chains.push_back({name, m, 1.0});
    return testing::targets_of(chains);
}

TEST(MapChains, CandidatesOnThreadsAreEachChainsOwnFit)
{
    const MotionTargets targets = every_sample_mechanism();
    const MotionOptions o;
    const CardParams card = testing::a4_card();
    std::atomic<double> progress{0.0};
    const MotionDesign d = map_chains(targets, o, card, nullptr, &progress);
    ASSERT_EQ(d.problem.candidates.size(), targets.chains.size());
    EXPECT_DOUBLE_EQ(progress.load(), 0.2);
    for (std::size_t j = 0; j < targets.chains.size(); ++j) {
        const auto alone = fit_candidates(d.full_chains[j], card, d.problem.h_max);
        for (int k = 0; k < motion_kind_count; ++k) {
            const Candidate& a = alone[k];
            const Candidate& b = d.problem.candidates[j][k];
            SCOPED_TRACE(targets.chains[j].name + ", " + to_string(MotionKind(k)));
            EXPECT_EQ(a.error_mm, b.error_mm); // bit for bit (both inf when infeasible)
            EXPECT_EQ(a.why, b.why);
            ASSERT_EQ(a.mechanism.kind(), b.mechanism.kind());
            ASSERT_EQ(active_parameter_count(a.mechanism), active_parameter_count(b.mechanism));
            for (int i = 0; i < active_parameter_count(a.mechanism); ++i)
                EXPECT_EQ(parameter(a.mechanism, i), parameter(b.mechanism, i));
        }
    }
}

TEST(MapChains, ACancelledMappingThrows)
{
    CancelFlag cancel;
    cancel.cancel();
    EXPECT_THROW(
        map_chains(every_sample_mechanism(), MotionOptions{}, testing::a4_card(), &cancel, nullptr),
        Cancelled);
}

} // namespace
} // namespace popup::motion
