// linkage_chains on hand-made trees with known vertex counts and bone lengths.
#include <gtest/gtest.h>

#include "popup/motion/linkage_chains.hpp"

using namespace popup;

namespace {

/// Two frames of a still skeleton whose bones sit at `offsets` from their parents.
Animation still(const std::vector<Bone>& bones, const std::vector<Vec3>& offsets)
{
    Animation a;
    a.source = "tree";
    a.bones = bones;
    a.frame_times_s = {0.0, 0.04};
    std::vector<Eigen::Isometry3d> pose;
    for (const Vec3& o : offsets) {
        Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
        m.translation() = o;
        pose.push_back(m);
    }
    a.local = {pose, pose};
    a.bind_inverse.assign(bones.size(), Eigen::Isometry3d::Identity());
    return a;
}

/// Gives bone b counts[b] vertices (each fully weighted to it), in bone order.
void skin_with(Animation& a, const std::vector<int>& counts)
{
    for (size_t b = 0; b < counts.size(); ++b)
        for (int k = 0; k < counts[b]; ++k) {
            a.mesh.vertices.emplace_back(double(a.mesh.vertices.size()), double(k % 3), double(b));
            a.skin.push_back({{int(b), 1.0}});
        }
}

// root -> spine -> chest -> {neck -> head, larm -> lhand, rarm -> rhand, finger}
const std::vector<Bone> body = {{"root", -1}, {"spine", 0}, {"chest", 1}, {"neck", 2},
                                {"head", 3},  {"larm", 2},  {"lhand", 5}, {"rarm", 2},
                                {"rhand", 7}, {"finger", 2}};

std::vector<Vec3> body_offsets()
{
    return {Vec3(0, 0, 0),  Vec3(0, 3, 0),  Vec3(0, 3, 0), Vec3(0, 1, 0), Vec3(0, 2, 0),
            Vec3(-2, 0, 0), Vec3(-3, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(0.2, 0.1, 0)};
}

} // namespace

TEST(MotionChains, SplitsAtBranchesAndKeepsVertexCounts)
{
    Animation a = still(body, body_offsets());
    skin_with(a, {10, 10, 10, 5, 20, 10, 10, 10, 10, 1}); // 96 vertices
    // τp = 0.09: threshold 0.09 × 96 / 10 = 0.864 < 1: nothing is pruned (the thesis's rule
    // alone: the finger reaches 0.22 of a character 10 long, under min_chain_size).
    ChainOptions thesis;
    thesis.min_chain_size = 0.0;
    const auto chains = linkage_chains(a, thesis);
    ASSERT_EQ(chains.size(), 5u);
    EXPECT_EQ(chains[0].name, "chest");
    EXPECT_EQ(chains[0].bones, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(chains[0].parent_chain, -1);
    EXPECT_EQ(chains[1].name, "head");
    EXPECT_EQ(chains[1].bones, (std::vector<int>{3, 4}));
    EXPECT_EQ(chains[2].bones, (std::vector<int>{5, 6}));
    EXPECT_EQ(chains[3].bones, (std::vector<int>{7, 8}));
    EXPECT_EQ(chains[4].name, "finger");
    for (size_t c = 1; c < 5; ++c)
        EXPECT_EQ(chains[c].parent_chain, 0);
    EXPECT_EQ(chains[0].vertices.size(), 30u);
    EXPECT_EQ(chains[1].vertices.size(), 25u);
    EXPECT_NEAR(chains[1].weight, 25.0 / 96.0, 1e-12);
    EXPECT_NEAR(chains[4].weight, 1.0 / 96.0, 1e-12);
}

TEST(MotionChains, PrunesSmallLeafChainsIntoTheirParent)
{
    Animation a = still(body, body_offsets());
    skin_with(a, {10, 10, 10, 5, 20, 10, 10, 10, 10, 1});
    // τp = 0.2: threshold 1.92; the finger (1 vertex) goes, the head chain (25) stays.
    ChainOptions options;
    options.prune_fraction = 0.2;
    const auto chains = linkage_chains(a, options);
    ASSERT_EQ(chains.size(), 4u);
    EXPECT_EQ(chains[0].vertices.size(), 31u);
    EXPECT_EQ(chains[0].pruned, (std::vector<std::string>{"finger"}));
    EXPECT_NEAR(chains[0].weight, 31.0 / 96.0, 1e-12);
    // The finger's vertex is the 96th (bone order), now the chest chain's.
    EXPECT_EQ(chains[0].vertices.back(), 95);
    // τp = 3: threshold 28.8: every leaf chain (25, 20, 20, 1) goes into the root chain.
    options.prune_fraction = 3.0;
    const auto all = linkage_chains(a, options);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].vertices.size(), 96u);
    EXPECT_NEAR(all[0].weight, 1.0, 1e-12);
    EXPECT_EQ(all[0].pruned.size(), 4u);
}

TEST(MotionChains, ALoneRemainingChildContinuesItsParentsChain)
{
    // root -> arm -> {hand -> tip, nub}: pruning nub leaves arm one child, so one chain.
    Animation a =
        still({{"root", -1}, {"arm", 0}, {"hand", 1}, {"tip", 2}, {"nub", 1}},
              {Vec3(0, 0, 0), Vec3(5, 0, 0), Vec3(5, 0, 0), Vec3(3, 4, 0), Vec3(0, 0.1, 0)});
    // No mesh: bone lengths 0, 5, 5, 5, 0.1; mean 3.02; τp 0.09 -> 0.2718 > 0.1.
    const auto chains = linkage_chains(a, {});
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_EQ(chains[0].name, "tip");
    EXPECT_EQ(chains[0].bones, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(chains[0].pruned, (std::vector<std::string>{"nub"}));
    EXPECT_NEAR(chains[0].weight, 1.0, 1e-12);
    // Without pruning: three chains weighted by length: root+arm 5, hand+tip 10, nub 0.1.
    ChainOptions keep;
    keep.prune_fraction = 0.0;
    keep.min_chain_size = 0.0;
    const auto three = linkage_chains(a, keep);
    ASSERT_EQ(three.size(), 3u);
    EXPECT_EQ(three[0].name, "arm");
    EXPECT_NEAR(three[0].weight, 5.0 / 15.1, 1e-12);
    EXPECT_NEAR(three[1].weight, 10.0 / 15.1, 1e-12);
    EXPECT_NEAR(three[2].weight, 0.1 / 15.1, 1e-12);
}

namespace {

// root -> spine -> chest -> {neck -> head -> {jaw -> jaw_end, eyelid, head_end},
//                            larm -> lhand -> {finger1 -> finger2 -> finger_end, thumb ->
//                            thumb_end}}
// root -> leg -> shin -> foot. Units cm: 218 tall (foot at -95, head_end at 123).
const std::vector<Bone> person = {
    {"root", -1},      {"spine", 0},    {"chest", 1},    {"neck", 2},        {"head", 3},
    {"jaw", 4},        {"jaw_end", 5},  {"eyelid", 4},   {"head_end", 4},    {"larm", 2},
    {"lhand", 9},      {"finger1", 10}, {"finger2", 11}, {"finger_end", 12}, {"thumb", 10},
    {"thumb_end", 14}, {"leg", 0},      {"shin", 16},    {"foot", 17}};

const std::vector<Vec3> person_offsets = {
    Vec3(0, 0, 0),  Vec3(0, 50, 0),  Vec3(0, 30, 0),  Vec3(0, 15, 0), Vec3(0, 10, 0),
    Vec3(0, -3, 4), Vec3(0, -5, 5),  Vec3(3, 7, 8),   Vec3(0, 18, 0), Vec3(20, 0, 0),
    Vec3(50, 0, 0), Vec3(9, 0, 0),   Vec3(4, 0, 0),   Vec3(3, 0, 0),  Vec3(3, 0, 3),
    Vec3(3, 0, 0),  Vec3(10, -5, 0), Vec3(0, -45, 0), Vec3(0, -45, 0)};

/// The person over 11 frames, each bone of `turning` rotating about z from 0 to `degrees`.
Animation person_moving(const std::vector<int>& turning, double degrees)
{
    Animation a = still(person, person_offsets);
    const auto rest = a.local[0];
    a.local.clear();
    a.frame_times_s.clear();
    for (int f = 0; f <= 10; ++f) {
        auto pose = rest;
        for (int b : turning)
            pose[b].rotate(Eigen::AngleAxisd(degrees * M_PI / 180.0 * f / 10.0, Vec3::UnitZ()));
        a.local.push_back(pose);
        a.frame_times_s.push_back(f / 30.0);
    }
    return a;
}

std::vector<std::string> names_of(const std::vector<LinkageChain>& chains)
{
    std::vector<std::string> out;
    for (const LinkageChain& c : chains)
        out.push_back(c.name);
    return out;
}

} // namespace

TEST(MotionChains, FingersAndFaceBonesArePartOfTheLimbAndHeadTheyHangFrom)
{
    // min_chain_size 0.15 x 218 = 32.7 cm: the thumb (4.24+3), eyelid (11.4), jaw (5+7.07),
    // finger (9+4+3 = 16) and the head's end (18) go, shortest first; the neck and head (15+10)
    // then reach 43 with their end and stay. The root branches: a chain of its own.
    const auto chains = linkage_chains(person_moving({}, 0.0), {});
    ASSERT_EQ(names_of(chains),
              (std::vector<std::string>{"root", "chest", "head", "lhand", "foot"}));
    EXPECT_EQ(chains[2].bones, (std::vector<int>{3, 4}));
    EXPECT_EQ(chains[2].pruned, (std::vector<std::string>{"eyelid", "jaw_end", "head_end"}));
    EXPECT_NEAR(chains[2].reach, 43.0, 1e-9);
    EXPECT_EQ(chains[3].pruned, (std::vector<std::string>{"thumb_end", "finger_end"}));
    EXPECT_NEAR(chains[3].reach, 70.0 + 16.0, 1e-9); // the arm and its longest finger
    // The thesis's τp alone (1.6 cm here) keeps all ten chains.
    ChainOptions thesis;
    thesis.min_chain_size = 0.0;
    EXPECT_EQ(linkage_chains(person_moving({}, 0.0), thesis).size(), 10u);
}

TEST(MotionChains, FingersStayChainsWhenTheyAreAllThatMoves)
{
    // The finger and thumb curl 60°: their tips move 7 and 3 cm against the hand (over a tenth
    // of their reach, 16 and 7.2) and nothing else moves: they are chains again; the still face
    // bones are not.
    const auto fingers = linkage_chains(person_moving({11, 14}, 60.0), {});
    EXPECT_EQ(names_of(fingers), (std::vector<std::string>{"root", "chest", "head", "lhand",
                                                           "finger_end", "thumb_end", "foot"}));
    // The arm swinging too: the fingers are part of the arm again.
    const auto arm = linkage_chains(person_moving({9, 11, 14}, 60.0), {});
    EXPECT_EQ(names_of(arm), (std::vector<std::string>{"root", "chest", "head", "lhand", "foot"}));
}
