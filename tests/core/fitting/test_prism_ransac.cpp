#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "fitting/card_hinge.hpp"
#include "fitting/synthetic_models.hpp"
#include "popup/fitting/prism_ransac.hpp"
#include "popup/fitting/surface_samples.hpp"

using namespace popup;
using namespace popup::testing;

TEST(PrismRansac, StoppingProbabilityFollowsSchnabel)
{
    // One draw finds a shape of n of N samples with n / (4 · N · hosts · levels · 2^(k−1)).
    EXPECT_DOUBLE_EQ(draw_probability(100, 1000, 2, 1, 5), 100.0 / (4 * 1000 * 5 * 2));
    EXPECT_DOUBLE_EQ(draw_probability(100, 1000, 4, 2, 5), 100.0 / (4 * 1000 * 2 * 5 * 8));
    // P(n, s) = 1 − (1 − P)^s.
    const double p = 500.0 / (4 * 1000 * 5 * 2);
    EXPECT_NEAR(found_probability(500, 1000, 2, 1, 5, 300), 1 - std::pow(1 - p, 300), 1e-12);
    EXPECT_DOUBLE_EQ(found_probability(500, 1000, 2, 1, 5, 0), 0.0);
}

TEST(PrismRansac, PrimitiveSearchStopsAtItsCancelFlag)
{
    const SurfaceSamples samples = sample_surface(cuboid_model(), 2000, 1);
    PrismHost card;
    card.length = 210;
    card.across_min = -148;
    card.across_max = 148;
    CancelFlag flag;
    flag.cancel();
    RansacOptions o;
    o.cancel = &flag;
    EXPECT_THROW(fit_prisms(samples, card, o), Cancelled);
    o.cancel = nullptr;
    // Not cancelled, the same search finds the box (the model is in its own frame here: x in
    // [-20, 20], y in [0, 120], z in [0, 30] stands on the card's pair as it is).
    const RansacResult r = fit_prisms(samples, card, o);
    ASSERT_GE(r.prisms.size(), 1u);
    EXPECT_EQ(r.prisms[0].kind, Prism::Kind::rectangular);
    EXPECT_NEAR(r.prisms[0].height, 30, 0.02 * 30);
    EXPECT_NEAR(r.prisms[0].s1, 20, 0.02 * 40);
    EXPECT_NEAR(r.prisms[0].a1 - r.prisms[0].a0, 120, 0.02 * 120);
}

TEST(PrismRansac, TwoLanesFindWhatOneFinds)
{
    // The draws tried on two cores, batches ahead: the same prisms, owners, draws and stop as
    // one draw after another (a house: a box and its roof; a figure: many rounds, no clear win).
    for (const ModelMesh& model : {house_model(), figure_model()}) {
        const SurfaceSamples samples = sample_surface(model, 6000, 3);
        const PrismHost card = card_hinge();
        RansacOptions o;
        o.threshold = 0.8;
        o.min_points = 40;
        const RansacResult one = fit_prisms(samples, card, o);
        o.lanes = 2;
        const RansacResult two = fit_prisms(samples, card, o);
        EXPECT_EQ(one.draws, two.draws);
        EXPECT_EQ(one.stopped_by_probability, two.stopped_by_probability);
        EXPECT_EQ(one.owner, two.owner);
        EXPECT_EQ(one.on_base, two.on_base);
        EXPECT_EQ(one.hosts.size(), two.hosts.size());
        ASSERT_EQ(one.prisms.size(), two.prisms.size());
        for (size_t k = 0; k < one.prisms.size(); ++k) {
            const Prism &a = one.prisms[k], &b = two.prisms[k];
            EXPECT_EQ(a.kind, b.kind);
            EXPECT_EQ(a.host, b.host);
            EXPECT_EQ(a.inliers, b.inliers);
            for (auto [x, y] : {std::pair{a.a0, b.a0},
                                {a.a1, b.a1},
                                {a.s0, b.s0},
                                {a.s1, b.s1},
                                {a.height, b.height},
                                {a.apex_s, b.apex_s}})
                EXPECT_EQ(x, y); // bit for bit
        }
    }
}
