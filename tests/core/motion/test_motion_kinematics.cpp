// Each motion mechanism's closed-form point path against the simulator (simulate_fold of the
// scaffold the library's generators build), which shares no code with the closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/motion_kinematics.hpp"
#include "motion_fixtures.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace popup::motion {
namespace {

using testing::build;
using testing::Built;
using testing::sample_mechanism;
using testing::samples;

TEST(MotionKinematics, PointPathEqualsTheSimulatorsOverTheFold)
{
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [kind, m] : samples()) {
        const Built b = build(m);
        // The carried point at the design state lies on one of the mechanism's patches (the
        // first one built: the rotation arm's tip also touches the other wing's edge at 180°);
        // the simulator's pose of that patch carries it.
        const Vec3 design = mechanism_point(m, M_PI);
        int carrier = -1;
        for (int id : b.patches) {
            const Patch* patch = b.scaffold.find_patch(id);
            if (carrier < 0 && patch->contains(design, 1e-9))
                carrier = id;
        }
        ASSERT_GE(carrier, 0) << kind;
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << kind;
        const int index = b.scaffold.patch_index(carrier);
        double worst = 0;
        for (const FoldState& state : sweep.value.states) {
            const Vec3 simulated = state.poses[index].apply(design);
            const Vec3 closed = mechanism_point(m, state.angle);
            worst = std::max(worst, (simulated.head<2>() - closed.head<2>()).norm());
        }
        EXPECT_LT(worst, 1e-6) << kind << ": card (x, y) differs by " << worst << " mm";
    }
}

TEST(MotionKinematics, AMergedArmCarriesEachPartWithItsWingAsTheSimulatorDoes)
{
    // rotation_carried_point moves a point of the arm's wing rigidly with it. Points spread over
    // the wing that carries the tip (its centroid, and halfway from there to each corner), given
    // by their card (x, y) when open, must follow the simulator's pose of that wing, on the fold
    // and on both sides of a floating layer; at the tip it is mechanism_point.
    std::vector<double> angles;
    for (int k = 0; k <= 36; ++k)
        angles.push_back(M_PI * k / 36);
    for (const auto& [name, m] : std::vector<std::pair<std::string, MotionMechanism>>{
             {"on the fold", sample_mechanism(MotionKind::rotation)},
             {"on side_ground", testing::off_fold_rotation(1)},
             {"on side_backdrop", testing::off_fold_rotation(-1)}}) {
        const Built b = build(m);
        const Vec3 tip = mechanism_point(m, M_PI);
        const Patch* wing = nullptr;
        for (int id : b.patches) {
            const Patch* patch = b.scaffold.find_patch(id);
            if (!wing && patch->contains(tip, 1e-9))
                wing = patch;
        }
        ASSERT_NE(wing, nullptr) << name;
        std::vector<Vec3> points{wing->centroid()};
        for (const Vec3& corner : wing->outer)
            points.push_back((wing->centroid() + corner) / 2);
        const Result<FoldSweep> sweep = simulate_fold(b.scaffold, angles);
        ASSERT_TRUE(sweep.ok && sweep.value.complete) << name;
        const int index = b.scaffold.patch_index(wing->id);
        double worst = 0, at_tip = 0;
        for (const FoldState& state : sweep.value.states) {
            for (const Vec3& q : points) {
                const Vec3 simulated = state.poses[index].apply(q);
                const Vec3 carried = rotation_carried_point(m, q.head<2>(), state.angle);
                worst = std::max(worst, (simulated - carried).norm());
            }
            at_tip = std::max(at_tip, (rotation_carried_point(m, tip.head<2>(), state.angle) -
                                       mechanism_point(m, state.angle))
                                          .norm());
        }
        EXPECT_LT(worst, 1e-6) << name << ": " << worst << " mm from the simulator's pose";
        EXPECT_LT(at_tip, 1e-9) << name;
    }
}

} // namespace
} // namespace popup::motion
