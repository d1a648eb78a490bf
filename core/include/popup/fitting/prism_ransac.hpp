#pragma once
#include "popup/fitting/prism_types.hpp"
#include "popup/fitting/surface_samples.hpp"

namespace popup {

/// Volumetric RANSAC of rectangular and triangular prisms (thesis Algorithms 5.1 and 5.2) on
/// samples in the card frame, starting from `card` (the central fold). Minimal samples are
/// drawn localised (Schnabel et al. 2007): two points for a rectangular prism, four for a
/// triangular one. A candidate must enclose no sample deeper than ε (it lies inside the model)
/// and scores by the samples on its faces; the best is kept once the probability that a larger
/// one was overlooked is below 1 − p_t; the search ends when a prism of τ samples would have
/// been found with probability p_t (docs/MATH.md, Fitting). Deterministic for a seed.
RansacResult fit_prisms(const SurfaceSamples& samples, const PrismHost& card,
                        const RansacOptions& options);

/// Appends the hosts a rectangular prism `m` (the `index`-th) on a flat host offers: its top
/// (over its middle, first) and each side with the page beyond it (mirrors build_parallel_box).
void offer_box_pairs(const Prism& m, int index, std::vector<PrismHost>& hosts);

/// The probability that one localised minimal sample of k points draws a given shape of n of
/// the N remaining samples when the search runs over `hosts` hosts and `levels` cell sizes:
/// n / (4 · N · hosts · levels · 2^(k−1)) (a quarter of the samples inside a shape generate it).
double draw_probability(double n, double N, int k, int hosts, int levels);
/// P(n, s) = 1 − (1 − draw_probability)^s: the shape was drawn at least once in s draws.
double found_probability(double n, double N, int k, int hosts, int levels, long draws);

} // namespace popup
