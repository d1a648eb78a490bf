// Each kind's mechanism from its named fields, the library's params it is built with, and what
// follows from them.
#include <gtest/gtest.h>

#include <cmath>

#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

TEST(MotionParameters, EachKindIsMadeFromItsNamedFields)
{
    const RotationMotion r = rotation_mechanism(1, 2, 3, 4, 5).rotation();
    EXPECT_EQ(r.offset, 1);
    EXPECT_EQ(r.spine, 2);
    EXPECT_EQ(r.run, 3);
    EXPECT_EQ(r.arm, 4);
    EXPECT_EQ(r.hinge, 5);
    EXPECT_EQ(rotation_mechanism(1, 2, 3, 4).rotation().hinge, 0); // on the fold
    const VerticalMotion v = vertical_mechanism(1, 2, 3, 0.4).vertical();
    EXPECT_EQ(v.offset, 1);
    EXPECT_EQ(v.side, 2);
    EXPECT_EQ(v.height, 3);
    EXPECT_EQ(v.wall_angle, 0.4);
    const HorizontalMotion h = horizontal_mechanism(1, 2, 3, 4, 5).horizontal();
    EXPECT_EQ(h.offset, 1);
    EXPECT_EQ(h.width, 2);
    EXPECT_EQ(h.run_ground, 3);
    EXPECT_EQ(h.run_backdrop, 4);
    EXPECT_EQ(h.reach, 5);
    const DiagonalMotion d = diagonal_mechanism(1, 2, 0.3, 4, 5, 6, 7, 8).diagonal();
    EXPECT_EQ(d.v_fold.offset, 1);
    EXPECT_EQ(d.v_fold.run, 2);
    EXPECT_EQ(d.v_fold.hinge_angle, 0.3);
    EXPECT_EQ(d.v_fold.spine, 4);
    EXPECT_EQ(d.step.offset, 5);
    EXPECT_EQ(d.step.width, 6);
    EXPECT_EQ(d.step.run_ground, 7);
    EXPECT_EQ(d.step.run_backdrop, 8);
    const StationaryMotion s = layer_mechanism(1, 2, 3, 4, 5, -6).stationary();
    EXPECT_EQ(s.offset, 1);
    EXPECT_EQ(s.width, 2);
    EXPECT_EQ(s.height, 3);
    EXPECT_EQ(s.support, 4);
    EXPECT_EQ(s.overhang, 5);
    EXPECT_EQ(s.anchor, -6);
}

TEST(MotionParameters, TheFieldsTheSearchDoesNotStepAreFixed)
{
    // The thesis's vertical translation is the half v-box; its diagonal's spine stands at 180°.
    EXPECT_FALSE(vertical_params(vertical_mechanism(1, 20, 30, 0.7)).back);
    EXPECT_FALSE(VerticalMotion{}.back);
    EXPECT_EQ(diagonal_v_fold(diagonal_mechanism(1, 60, 0.7, 50, 10, 12, 16, 12)).spine_angle,
              M_PI / 2);
    EXPECT_EQ(DiagonalMotion{}.v_fold.spine_angle, M_PI / 2);
}

TEST(MotionParameters, AnOffFoldArmStartsAtItsLayersStart)
{
    // On the fold the arm starts at offset; off it the layer does, and the arm at 0 on its side.
    EXPECT_EQ(rotation_params(rotation_mechanism(60, 40, 30, 25)).offset, 60);
    EXPECT_FALSE(rotation_off_fold(rotation_mechanism(60, 40, 30, 25)));
    EXPECT_FALSE(rotation_off_fold(testing::sample_mechanism(MotionKind::stationary)));
    for (double side : {1.0, -1.0}) {
        const MotionMechanism m = testing::off_fold_rotation(side); // 50, 40, 25, 30, ±30
        EXPECT_TRUE(rotation_off_fold(m));
        const RotationArmParams r = rotation_params(m);
        EXPECT_EQ(r.offset, 0);
        EXPECT_EQ(r.spine, 40);
        EXPECT_EQ(r.run, 25);
        EXPECT_EQ(r.arm, 30);
        const FloatingLayerParams f = rotation_layer(m);
        EXPECT_EQ(f.offset, 50);
        EXPECT_EQ(f.width, 40);
        EXPECT_EQ(f.support, 30);
        EXPECT_EQ(f.height, rotation_layer_height(25, 30));
        EXPECT_EQ(f.height, 31); // the arm, 1 mm to spare
        EXPECT_EQ(f.overhang, 0);
        EXPECT_EQ(rotation_side(m), side > 0 ? LayerSide::ground : LayerSide::backdrop);
    }
}

TEST(MotionParameters, FoldOffsetIsWhereEachKindStartsAlongTheFold)
{
    for (MotionKind kind : testing::all_kinds) {
        MotionMechanism m = testing::sample_mechanism(kind);
        const double before = fold_offset(m);
        fold_offset(m) += 7;
        EXPECT_EQ(fold_offset(m), before + 7) << to_string(kind);
        EXPECT_EQ(mechanism_point(m, M_PI).y(),
                  mechanism_point(testing::sample_mechanism(kind), M_PI).y() + 7)
            << to_string(kind) << ": the whole mechanism moves along the fold";
    }
    MotionMechanism d = testing::sample_mechanism(MotionKind::diagonal);
    fold_offset(d) = 3;
    EXPECT_EQ(d.diagonal().v_fold.offset, 3);
    EXPECT_EQ(d.diagonal().step.offset, 10); // along the spine: it moves with the v-fold
}

TEST(MotionParameters, MechanismHeightIsTheCarryingPatchsAtTheOpenCard)
{
    using testing::sample_mechanism;
    EXPECT_EQ(mechanism_height(sample_mechanism(MotionKind::vertical)), 30);
    EXPECT_EQ(mechanism_height(sample_mechanism(MotionKind::diagonal)), 10 + 12 / 2.0);
    EXPECT_EQ(mechanism_height(sample_mechanism(MotionKind::stationary)), 20);
    EXPECT_EQ(mechanism_height(sample_mechanism(MotionKind::horizontal)), 0);
    EXPECT_EQ(mechanism_height(sample_mechanism(MotionKind::rotation)), 0);
}

TEST(MotionParameters, EachKindHasADefaultMechanism)
{
    for (MotionKind kind : testing::all_kinds)
        EXPECT_EQ(default_mechanism(kind).kind(), kind);
    EXPECT_EQ(MotionMechanism{}.kind(), MotionKind::stationary);
    EXPECT_FALSE(rotation_off_fold(default_mechanism(MotionKind::rotation)));
}

} // namespace
} // namespace popup::motion
