// Each motion mechanism built with the library's generators on the A4 card: its sample
// parameters are feasible and the simulator's full check passes.
#include <gtest/gtest.h>

#include "motion/motion_feasibility.hpp"
#include "motion_fixtures.hpp"
#include "popup/model/card.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup::motion {
namespace {

using testing::build;
using testing::Built;
using testing::samples;

TEST(BuildMechanism, SampleParametersAreFeasibleAndTheDesignIsValid)
{
    CardParams card;
    card.depth = 148;
    for (const auto& [kind, m] : samples()) {
        EXPECT_EQ(infeasibility(m, card), "") << kind;
        const Built b = build(m);
        const ValidityReport report = check_validity(b.scaffold);
        EXPECT_TRUE(report.valid()) << kind;
    }
}

} // namespace
} // namespace popup::motion
