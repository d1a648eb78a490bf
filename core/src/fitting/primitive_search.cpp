#include "primitive_search.hpp"

#include <algorithm>
#include <atomic>
#include <future>
#include <utility>

namespace popup {

PrimitiveSearch search_primitives(const ModelMesh& model, const SurfaceSamples& model_samples,
                                  const std::vector<bool>& inner,
                                  const std::vector<Alignment>& alignments,
                                  const FitOptions& options, const CancelFlag* cancel)
{
    auto attempt = [&](const Alignment& a) {
        PrimitiveSearch t;
        t.samples = transformed(model_samples, a.model_to_card);
        const double diagonal = a.scale * model.diagonal();
        PrismHost card;
        card.name = "central fold";
        card.origin = Vec3::Zero();
        card.length = options.card.width;
        card.across_min = -options.card.depth;
        card.across_max = options.card.depth;
        RansacOptions& ro = t.ro;
        ro.threshold = options.threshold * diagonal;
        // τ in samples: the five visible faces of a cube of edge min_shape·diagonal.
        const double tau = options.min_shape * diagonal;
        ro.min_points =
            std::max(8.0, 5 * tau * tau / std::max(t.samples.spacing * t.samples.spacing, 1e-300));
        ro.probability = options.probability;
        ro.seed = options.seed;
        ro.max_primitives = options.max_mechanisms;
        ro.min_part = options.min_part_mm;
        ro.cancel = cancel;
        ro.inner = inner;
        ro.lanes = alignments.size() == 1 ? 2 : 1;
        t.fit = fit_prisms(t.samples, card, ro);
        size_t n = 0;
        for (size_t i = 0; i < t.fit.owner.size(); ++i)
            n += t.fit.on_principal[i] || t.fit.on_base[i];
        t.explained = t.fit.owner.empty() ? 0.0 : double(n) / double(t.fit.owner.size());
        return t;
    };
    // Each alignment's search is its own (same seed, its own samples): two run at a time on the
    // two cores a maker has, each as alone, then compared in order as before.
    std::vector<PrimitiveSearch> tried(alignments.size());
    std::atomic<size_t> next{0};
    auto search_next = [&] {
        for (size_t k = next++; k < alignments.size(); k = next++)
            tried[k] = attempt(alignments[k]);
    };
    if (alignments.size() > 1) {
        std::future<void> other = std::async(std::launch::async, search_next);
        search_next();
        other.get();
    } else {
        search_next();
    }
    // The alignment whose primitives' paper faces (not their open ends) explain the most
    // samples; the first (the mirror plane)
    // unless another explains a hundredth more (docs/MATH.md, "Which way is up").
    size_t chosen = 0;
    for (size_t k = 1; k < tried.size(); ++k)
        if (tried[k].explained > tried[chosen].explained + 0.01)
            chosen = k;
    PrimitiveSearch best = std::move(tried[chosen]);
    best.alignment = chosen;
    return best;
}

} // namespace popup
