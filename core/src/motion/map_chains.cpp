#include "map_chains.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>

#include "on_cores.hpp"

namespace popup::motion {

namespace {

// True when every chain has the same depth D (eq 6.7): one chain, or a character without depth
// (a planar skeleton). D then says nothing about which part is nearer, and E_d = |D − H| would
// only push the mechanisms with a height (v-box, diagonal, floating layer) away from the flat
// ones whatever the path (docs/DESIGN.md, Depth term without depth).
bool depths_all_equal(const std::vector<ChainTarget>& chains)
{
    for (const ChainTarget& c : chains)
        if (std::abs(c.depth - chains.front().depth) > 1e-9)
            return false;
    return true;
}

// Whether the maker chose chain `name` to animate (MotionOptions::animate_only; empty: all).
bool chosen(const MotionOptions& o, const std::string& name)
{
    return o.animate_only.empty() ||
           std::find(o.animate_only.begin(), o.animate_only.end(), name) != o.animate_only.end();
}

using Candidates = std::array<Candidate, motion_kind_count>;

// Every chain's candidates (fit_candidates), each chain's kind fitted as its own task on the
// machine's cores: the fits are independent and each the same on whatever thread makes it (a
// 4,500-frame capture's 7 chains took 0.66 s on one). The costliest kinds go first.
std::vector<Candidates> fit_all_candidates(const std::vector<ChainTarget>& chains,
                                           const CardParams& card, double h_max,
                                           const CancelFlag* cancel, std::atomic<double>* progress)
{
    std::vector<Candidates> out(chains.size());
    const MotionKind order[] = {MotionKind::diagonal, MotionKind::rotation, MotionKind::horizontal,
                                MotionKind::vertical, MotionKind::stationary};
    const std::size_t tasks = chains.size() * motion_kind_count;
    std::size_t done = 0;
    std::mutex progress_lock; // progress only grows
    run_on_cores(tasks, [&](std::size_t task) {
        stop_if_cancelled(cancel, "design_motion: mapping");
        const std::size_t j = task % chains.size();
        const MotionKind kind = order[task / chains.size()];
        out[j][int(kind)] = fit_candidate(kind, chains[j], card, h_max);
        const std::lock_guard<std::mutex> hold(progress_lock);
        ++done;
        if (progress)
            progress->store(0.2 * double(done) / double(tasks));
    });
    return out;
}

} // namespace

double layer_height_max(const MotionOptions& o)
{
    if (o.layer_height_max > 0)
        return o.layer_height_max;
    return 25.0 * std::sqrt(o.view.card.width * o.view.card.depth / (210.0 * 148.5));
}

MotionDesign map_chains(const MotionTargets& targets, const MotionOptions& o,
                        const CardParams& card, const CancelFlag* cancel,
                        std::atomic<double>* progress)
{
    MotionDesign d;
    AnnealProblem& p = d.problem;
    p.card = card;
    p.diagonal = targets.diagonal_mm;
    p.h_max = layer_height_max(o);
    p.motion_weight = o.motion_weight;
    p.depth_weight = o.depth_weight;
    p.collision_weight = o.collision_weight;
    std::vector<MotionKind>& mapped = d.mapped;
    // The search scores every k-th sample of a long path (search_target); the report, all.
    std::vector<ChainTarget>& full_chains = d.full_chains;
    for (std::size_t j = 0; j < targets.chains.size(); ++j) {
        ChainTarget c;
        c.name = targets.chains[j].name;
        c.s = targets.paths[j].s;
        c.target = targets.paths[j].effector;
        c.weight = targets.chains[j].weight;
        c.depth = targets.paths[j].depth;
        full_chains.push_back(c);
        p.chains.push_back(search_target(c));
    }
    stop_if_cancelled(cancel, "design_motion: mapping");
    p.candidates = fit_all_candidates(full_chains, card, p.h_max, cancel, progress);
    for (std::size_t j = 0; j < full_chains.size(); ++j) {
        const ChainTarget& c = full_chains[j];
        // A chain the maker did not choose is mapped to the floating layer: p.still then keeps
        // every later stage from moving it.
        d.unchosen.push_back(!chosen(o, c.name));
        mapped.push_back(
            d.unchosen.back()
                ? MotionKind::stationary
                : best_mapping(p.candidates[j], c, still_path_fraction * p.diagonal, p.diagonal));
    }
    for (MotionKind kind : mapped)
        p.still.push_back(kind == MotionKind::stationary);
    prepare_alike(p);
    if (depths_all_equal(p.chains))
        p.depth_weight = 0.0; // D is undefined (0.5 for all): E_d would only charge height
    return d;
}

} // namespace popup::motion
