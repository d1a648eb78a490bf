// load_trajectories: hand-written JSON files, their bones and tracks, and every malformed field.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "popup/motion/animation.hpp"

namespace fs = std::filesystem;
using namespace popup;

namespace {

std::string write_json(const std::string& name, const std::string& text)
{
    const fs::path dir = fs::temp_directory_path() / "popup_trajectories";
    fs::create_directories(dir);
    const fs::path path = dir / (name + ".json");
    std::ofstream(path) << text;
    return path.string();
}

struct Failure {
    DiagnosticCode code;
    std::string message;
};

Failure failure_of(const std::string& name, const std::string& text)
{
    const Result<Animation> r = load_trajectories(write_json(name, text));
    EXPECT_FALSE(r.ok) << name;
    if (r.ok || r.diagnostics.empty())
        return {DiagnosticCode::bad_option, ""};
    return {r.diagnostics[0].code, r.diagnostics[0].message};
}

} // namespace

TEST(MotionTrajectories, BonesFollowTheWrittenPoints)
{
    const std::string path = write_json("arm", R"({
      "format": "popup-trajectories", "version": 1, "frame_rate": 10,
      "effectors": [
        {"name": "hand", "parent": "elbow", "points": [[3, 0, 0], [2, 2, 1], [0, 3, 2]]},
        {"name": "elbow", "root": [1, 1], "points": [[2, 0], [2, 1], [1, 2]]}
      ]})");
    const Result<Animation> r = load_trajectories(path);
    ASSERT_TRUE(r.ok) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
    const Animation& a = r.value;
    ASSERT_EQ(a.bones.size(), 3u);
    // The parent effector comes first: elbow.root, elbow, then hand hanging from elbow.
    EXPECT_EQ(a.bones[0].name, "elbow.root");
    EXPECT_EQ(a.bones[0].parent, -1);
    EXPECT_EQ(a.bones[1].name, "elbow");
    EXPECT_EQ(a.bones[1].parent, 0);
    EXPECT_EQ(a.bones[2].name, "hand");
    EXPECT_EQ(a.bones[2].parent, 1);
    ASSERT_EQ(a.frames(), 3);
    EXPECT_DOUBLE_EQ(a.frame_times_s[2], 0.2);
    const Vec3 hand[3] = {Vec3(3, 0, 0), Vec3(2, 2, 1), Vec3(0, 3, 2)};
    const Vec3 elbow[3] = {Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)};
    for (int f = 0; f < 3; ++f) {
        const auto g = forward_kinematics(a, f);
        EXPECT_LT((g[0].translation() - Vec3(1, 1, 0)).norm(), 1e-12);
        EXPECT_LT((g[1].translation() - elbow[f]).norm(), 1e-12);
        EXPECT_LT((g[2].translation() - hand[f]).norm(), 1e-12);
    }
    // Half way between frames 1 and 2: the points' mean (translations are lerped).
    EXPECT_LT((forward_kinematics(a, 1.5)[2].translation() - 0.5 * (hand[1] + hand[2])).norm(),
              1e-12);
}

TEST(MotionTrajectories, TimesAndMovingRoots)
{
    const Result<Animation> r = load_trajectories(write_json("times", R"({
      "times": [0, 0.5, 2],
      "effectors": [{"name": "paw", "root": [[0, 0, 0], [1, 0, 0], [2, 0, 0]],
                     "points": [[0, 1], [1, 1], [2, 1]]}]})"));
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.value.frame_times_s, (std::vector<double>{0, 0.5, 2}));
    EXPECT_LT((forward_kinematics(r.value, 2)[0].translation() - Vec3(2, 0, 0)).norm(), 1e-12);
    EXPECT_LT((forward_kinematics(r.value, 2)[1].translation() - Vec3(2, 1, 0)).norm(), 1e-12);
}

TEST(MotionTrajectories, EachMalformedFileHasItsNamedError)
{
    const Failure cycle = failure_of("cycle", R"({"effectors": [
        {"name": "a", "parent": "b", "points": [[0, 0], [1, 0]]},
        {"name": "b", "parent": "a", "points": [[0, 1], [1, 1]]}]})");
    EXPECT_EQ(cycle.code, DiagnosticCode::skeleton_cycle);
    EXPECT_NE(cycle.message.find("a -> b -> a"), std::string::npos) << cycle.message;

    const Failure single = failure_of(
        "single", R"({"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0]]}]})");
    EXPECT_EQ(single.code, DiagnosticCode::single_frame);

    const Failure nan = failure_of(
        "nan", R"({"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0], [NaN, 0]]}]})");
    EXPECT_EQ(nan.code, DiagnosticCode::non_finite_animation);
    const Failure null = failure_of(
        "null", R"({"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0], [2, null]]}]})");
    EXPECT_EQ(null.code, DiagnosticCode::non_finite_animation);
    EXPECT_NE(null.message.find("effectors[0].points[1][1]"), std::string::npos) << null.message;
    const Failure huge = failure_of(
        "huge",
        R"({"effectors": [{"name": "a", "root": [0, 0], "points": [[1, 0], [1e999, 0]]}]})");
    EXPECT_EQ(huge.code, DiagnosticCode::non_finite_animation) << huge.message;

    EXPECT_EQ(failure_of("none", R"({"effectors": []})").code, DiagnosticCode::no_animation);
    EXPECT_EQ(failure_of("missing", R"({"frame_rate": 24})").code, DiagnosticCode::no_animation);
    EXPECT_EQ(failure_of("noframes", R"({"effectors": [{"name": "a", "root": [0, 0],
                                        "points": []}]})")
                  .code,
              DiagnosticCode::no_animation);

    const Failure lengths = failure_of("lengths", R"({"effectors": [
        {"name": "a", "root": [0, 0], "points": [[0, 0], [1, 0], [2, 0]]},
        {"name": "b", "root": [0, 0], "points": [[0, 1], [1, 1]]}]})");
    EXPECT_EQ(lengths.code, DiagnosticCode::bad_animation);
    EXPECT_NE(lengths.message.find("effectors[1].points has 2 points"), std::string::npos)
        << lengths.message;

    const Failure type = failure_of(
        "type", R"({"effectors": [{"name": "a", "root": [0, 0], "points": [[0, 0], "up"]}]})");
    EXPECT_EQ(type.code, DiagnosticCode::bad_animation);
    EXPECT_NE(type.message.find("effectors[0].points[1]"), std::string::npos) << type.message;

    EXPECT_EQ(failure_of("unknown", R"({"effectors": [{"name": "a", "root": [0, 0],
                         "points": [[0, 0], [1, 1]], "colour": 3}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("both", R"({"effectors": [{"name": "a", "root": [0, 0], "parent": "b",
                         "points": [[0, 0], [1, 1]]}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("orphan", R"({"effectors": [{"name": "a", "parent": "zz",
                         "points": [[0, 0], [1, 1]]}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("twice", R"({"effectors": [
        {"name": "a", "root": [0, 0], "points": [[0, 0], [1, 1]]},
        {"name": "a", "root": [0, 0], "points": [[0, 0], [1, 1]]}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("rate", R"({"frame_rate": 0, "effectors": [{"name": "a", "root": [0, 0],
                         "points": [[0, 0], [1, 1]]}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("slow", R"({"times": [0, 0], "effectors": [{"name": "a", "root": [0, 0],
                         "points": [[0, 0], [1, 1]]}]})")
                  .code,
              DiagnosticCode::bad_animation);
    EXPECT_EQ(failure_of("garbage", "{\"effectors\": [").code, DiagnosticCode::bad_json);
    const Result<Animation> absent = load_trajectories("/nonexistent/popup.json");
    ASSERT_FALSE(absent.ok);
    EXPECT_EQ(absent.diagnostics[0].code, DiagnosticCode::unreadable_model);
}
