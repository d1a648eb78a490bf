#include <gtest/gtest.h>

#include <cmath>

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
