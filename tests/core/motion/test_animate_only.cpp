// MotionOptions::animate_only, the chains the maker chose to animate: every stage (mapping,
// annealing, greedy finish, collision repair) holds the others still, the report says why, and
// a name no chain has is a bad option naming it and the chains found.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/design_from_targets.hpp"
#include "motion_fixtures.hpp"
#include "popup/refers_into_argument.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup::motion {
namespace {

using testing::Chain;
using testing::targets_of;

MotionOptions quick()
{
    MotionOptions o;
    o.view.card.width = 210;
    o.view.card.depth = 148;
    o.iterations = 1500;
    return o;
}

// Two chains that both animate when nothing is chosen (each its own mechanism, far apart).
std::vector<Chain> arm_and_head()
{
    return {{"arm", rotation_mechanism(20, 40, 30, 25), 0.6},
            {"head", vertical_mechanism(95, 20, 30, 40 * M_PI / 180), 0.4}};
}

POPUP_REFERS_INTO_ARGUMENT const ChainReport& chain(const MotionResult& r, const std::string& name)
{
    for (const ChainReport& c : r.chains)
        if (c.name == name)
            return c;
    throw std::runtime_error("no chain " + name);
}

bool says_not_chosen(const ChainReport& c)
{
    return c.reason.find("the maker did not choose it") != std::string::npos;
}

TEST(AnimateOnly, TheTableListsItAsNamesAndItIsEmptyByDefault)
{
    EXPECT_TRUE(MotionOptions{}.animate_only.empty());
    int found = 0;
    for (const OptionField& f : motion_option_fields())
        if (f.name == "animate_only") {
            ++found;
            EXPECT_EQ(f.kind, OptionKind::names);
            EXPECT_TRUE(f.group.empty());
            EXPECT_EQ(f.range(), "a list of names");
        }
    EXPECT_EQ(found, 1);
}

TEST(AnimateOnly, WithNothingChosenBothChainsAnimate)
{
    const Result<MotionResult> r = design_from_targets(targets_of(arm_and_head()), quick());
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.valid);
    EXPECT_EQ(chain(r.value, "arm").status, "animated");
    EXPECT_EQ(chain(r.value, "head").status, "animated");
}

TEST(AnimateOnly, TheChosenChainAnimatesAndTheOtherIsHeldStillWithTheMakersReason)
{
    MotionOptions o = quick();
    o.animate_only = {"head"};
    const Result<MotionResult> r = design_from_targets(targets_of(arm_and_head()), o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.value.valid);
    EXPECT_TRUE(check_validity(r.value.scaffold).valid());
    const ChainReport &head = chain(r.value, "head"), &arm = chain(r.value, "arm");
    EXPECT_EQ(head.status, "animated") << head.reason;
    EXPECT_EQ(head.mapping, "vertical");
    EXPECT_FALSE(says_not_chosen(head));
    EXPECT_EQ(arm.status, "stationary");
    EXPECT_EQ(arm.mapping, "stationary");
    EXPECT_TRUE(says_not_chosen(arm)) << arm.reason;
    // The reach floor and the best alone do not depend on the choice.
    const Result<MotionResult> all = design_from_targets(targets_of(arm_and_head()), quick());
    ASSERT_TRUE(all.ok);
    EXPECT_EQ(arm.floor_mm, chain(all.value, "arm").floor_mm);
    EXPECT_EQ(arm.bound_mm, chain(all.value, "arm").bound_mm);
    EXPECT_EQ(r.value.weighted_floor, all.value.weighted_floor);
}

TEST(AnimateOnly, ALongSearchNeverMovesAnUnchosenChain)
{
    // Three chains, the search and the finishing stages free to remap: the two not chosen must
    // stay still whatever the seed.
    const std::vector<Chain> chains = {
        {"arm", rotation_mechanism(20, 40, 30, 25), 0.4},
        {"head", vertical_mechanism(95, 20, 30, 40 * M_PI / 180), 0.3},
        {"tail", horizontal_mechanism(150, 30, 40, 15, 60), 0.3}};
    for (std::uint64_t seed : {1, 2, 3}) {
        MotionOptions o = quick();
        o.seed = seed;
        o.iterations = 4000;
        o.animate_only = {"tail"};
        const Result<MotionResult> r = design_from_targets(targets_of(chains), o);
        ASSERT_TRUE(r.ok);
        EXPECT_EQ(chain(r.value, "tail").status, "animated") << seed;
        for (const char* name : {"arm", "head"}) {
            const ChainReport& c = chain(r.value, name);
            EXPECT_EQ(c.mapping, "stationary") << name << " seed " << seed;
            EXPECT_TRUE(says_not_chosen(c)) << c.reason;
        }
    }
}

TEST(AnimateOnly, NamingEveryChainIsTheDefaultDesign)
{
    MotionOptions o = quick();
    o.animate_only = {"arm", "head"};
    const Result<MotionResult> named = design_from_targets(targets_of(arm_and_head()), o);
    const Result<MotionResult> all = design_from_targets(targets_of(arm_and_head()), quick());
    ASSERT_TRUE(named.ok && all.ok);
    EXPECT_EQ(named.value.weighted_error, all.value.weighted_error);
    EXPECT_EQ(named.value.cost, all.value.cost);
    for (std::size_t j = 0; j < all.value.chains.size(); ++j) {
        EXPECT_EQ(named.value.chains[j].mapping, all.value.chains[j].mapping);
        EXPECT_EQ(named.value.chains[j].reason, all.value.chains[j].reason);
    }
}

TEST(AnimateOnly, AnUnknownNameIsABadOptionNamingItAndTheChainsFound)
{
    MotionOptions o = quick();
    o.animate_only = {"head", "Hand.L", "tail"};
    const Result<MotionResult> r = design_from_targets(targets_of(arm_and_head()), o);
    ASSERT_FALSE(r.ok);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    const Diagnostic& d = r.diagnostics.front();
    EXPECT_EQ(d.code, DiagnosticCode::bad_option);
    EXPECT_EQ(d.parameter.value_or(""), "animate_only");
    EXPECT_EQ(d.message, "MotionOptions.animate_only: no chain is named \"Hand.L\", \"tail\"; the "
                         "chains found: arm, head");
}

} // namespace
} // namespace popup::motion
