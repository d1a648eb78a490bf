// The search's indexed view of a mechanism's parameters: each index is one named field of its
// kind's params, in the order the search has always stepped them.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "motion/parameter_table.hpp"
#include "motion_fixtures.hpp"

namespace popup::motion {
namespace {

using Reader = std::function<double(const MotionMechanism&)>;

// Every field of each kind's params, read by name (those the search does not step too).
std::vector<std::pair<std::string, Reader>> named_fields(MotionKind kind)
{
    using M = const MotionMechanism&;
    switch (kind) {
    case MotionKind::vertical:
        return {{"offset", [](M m) { return m.vertical().offset; }},
                {"side", [](M m) { return m.vertical().side; }},
                {"height", [](M m) { return m.vertical().height; }},
                {"wall_angle", [](M m) { return m.vertical().wall_angle; }},
                {"back", [](M m) { return double(m.vertical().back); }}};
    case MotionKind::diagonal:
        return {{"offset", [](M m) { return m.diagonal().v_fold.offset; }},
                {"run", [](M m) { return m.diagonal().v_fold.run; }},
                {"hinge_angle", [](M m) { return m.diagonal().v_fold.hinge_angle; }},
                {"spine", [](M m) { return m.diagonal().v_fold.spine; }},
                {"spine_angle", [](M m) { return m.diagonal().v_fold.spine_angle; }},
                {"step_offset", [](M m) { return m.diagonal().step.offset; }},
                {"step_width", [](M m) { return m.diagonal().step.width; }},
                {"run_ground", [](M m) { return m.diagonal().step.run_ground; }},
                {"run_backdrop", [](M m) { return m.diagonal().step.run_backdrop; }}};
    case MotionKind::horizontal:
        return {{"offset", [](M m) { return m.horizontal().offset; }},
                {"width", [](M m) { return m.horizontal().width; }},
                {"run_ground", [](M m) { return m.horizontal().run_ground; }},
                {"run_backdrop", [](M m) { return m.horizontal().run_backdrop; }},
                {"reach", [](M m) { return m.horizontal().reach; }}};
    case MotionKind::rotation:
        return {{"offset", [](M m) { return m.rotation().offset; }},
                {"spine", [](M m) { return m.rotation().spine; }},
                {"run", [](M m) { return m.rotation().run; }},
                {"arm", [](M m) { return m.rotation().arm; }},
                {"hinge", [](M m) { return m.rotation().hinge; }}};
    case MotionKind::stationary:
        break;
    }
    return {{"offset", [](M m) { return m.stationary().offset; }},
            {"width", [](M m) { return m.stationary().width; }},
            {"height", [](M m) { return m.stationary().height; }},
            {"support", [](M m) { return m.stationary().support; }},
            {"overhang", [](M m) { return m.stationary().overhang; }},
            {"anchor", [](M m) { return m.stationary().anchor; }}};
}

TEST(ParameterTable, SteppingParameterKChangesExactlyItsNamedField)
{
    for (const auto& [label, m] : testing::samples()) {
        const MotionKind kind = m.kind();
        for (int k = 0; k < parameter_count(kind); ++k) {
            const std::string name = parameter_info(kind, k).name;
            SCOPED_TRACE(label + " parameter " + std::to_string(k) + " (" + name + ")");
            MotionMechanism stepped = m;
            parameter(stepped, k) += 1.25;
            int named = 0;
            for (const auto& [field, read] : named_fields(kind)) {
                if (field == name) {
                    ++named;
                    EXPECT_EQ(read(stepped), read(m) + 1.25);
                    EXPECT_EQ(parameter(stepped, k), read(stepped)); // the const view too
                } else {
                    EXPECT_EQ(read(stepped), read(m)) << field << " changed too";
                }
            }
            EXPECT_EQ(named, 1) << "no field of the params is named " << name;
        }
    }
}

TEST(ParameterTable, TheSearchStepsTheParametersInItsOrder)
{
    // The annealing, its crossover and the polish step parameters by index: another order
    // (or role) would make other designs (docs/MOTION_RESULTS.md).
    using R = ParameterRole;
    const std::vector<std::pair<MotionKind, std::vector<std::pair<std::string, R>>>> expected = {
        {MotionKind::vertical,
         {{"offset", R::position},
          {"side", R::length},
          {"height", R::length},
          {"wall_angle", R::angle}}},
        {MotionKind::diagonal,
         {{"offset", R::position},
          {"run", R::length},
          {"hinge_angle", R::angle},
          {"spine", R::length},
          {"step_offset", R::length},
          {"step_width", R::length},
          {"run_ground", R::length},
          {"run_backdrop", R::length}}},
        {MotionKind::horizontal,
         {{"offset", R::position},
          {"width", R::length},
          {"run_ground", R::length},
          {"run_backdrop", R::length},
          {"reach", R::length}}},
        {MotionKind::rotation,
         {{"offset", R::position},
          {"spine", R::length},
          {"run", R::length},
          {"arm", R::length},
          {"hinge", R::position}}},
        {MotionKind::stationary,
         {{"offset", R::position},
          {"width", R::length},
          {"height", R::length},
          {"support", R::length},
          {"overhang", R::length},
          {"anchor", R::position}}}};
    for (const auto& [kind, rows] : expected) {
        ASSERT_EQ(parameter_count(kind), int(rows.size())) << to_string(kind);
        for (int k = 0; k < int(rows.size()); ++k) {
            EXPECT_EQ(parameter_info(kind, k).name, rows[k].first) << to_string(kind) << " " << k;
            EXPECT_EQ(parameter_info(kind, k).role, rows[k].second) << to_string(kind) << " " << k;
        }
    }
}

TEST(ParameterTable, AnOnFoldRotationDoesNotStepItsHinge)
{
    EXPECT_EQ(active_parameter_count(testing::sample_mechanism(MotionKind::rotation)), 4);
    EXPECT_EQ(active_parameter_count(testing::off_fold_rotation(1)), 5);
    EXPECT_EQ(active_parameter_count(testing::off_fold_rotation(-1)), 5);
    for (MotionKind kind : testing::all_kinds) {
        if (kind != MotionKind::rotation) {
            EXPECT_EQ(active_parameter_count(testing::sample_mechanism(kind)),
                      parameter_count(kind));
        }
    }
}

TEST(ParameterTable, AnIndexOffTheTableOrAnotherKindsFieldsAreNamedErrors)
{
    MotionMechanism m = testing::sample_mechanism(MotionKind::vertical);
    try {
        parameter(m, 4);
        ADD_FAILURE() << "no error";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("parameter 4 of a vertical"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("[0, 3]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parameter_info(MotionKind::rotation, -1), std::out_of_range);
    try {
        (void)m.rotation();
        ADD_FAILURE() << "no error";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("rotation parameters asked for, but it is a vertical"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace popup::motion
