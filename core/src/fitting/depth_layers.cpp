#include "popup/fitting/depth_layers.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "projected_faces.hpp"

namespace popup {

Result<std::vector<DepthLayer>> depth_layers(const ModelMesh& model, const Scaffold& scaffold,
                                             int patch_id, const DepthLayerOptions& options)
{
    Result<std::vector<DepthLayer>> r;
    const Result<ModelMesh> checked = check_model(model);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    auto bad = [&](const std::string& option, double value, const std::string& range) {
        std::ostringstream m;
        m << "depth layers: " << option << " = " << value << ", must be " << range;
        r.fail(DiagnosticCode::bad_option, m.str(), about_parameter(option));
    };
    if (!(options.max_layers >= 1 && options.max_layers <= 64))
        bad("max_layers", options.max_layers, "1 to 64");
    if (!(options.min_area_fraction >= 0 && options.min_area_fraction < 1))
        bad("min_area_fraction", options.min_area_fraction, "0 or more and below 1");
    if (!std::isfinite(options.min_gap))
        bad("min_gap", options.min_gap, "a finite length in mm (<= 0 for 2 % of the model)");
    const Result<ProfileFrame> frame = profile_frame(scaffold, patch_id);
    if (!frame.ok)
        r.fail_with(frame.diagnostics);
    if (!r.ok)
        return r;
    const Patch* patch = scaffold.find_patch(patch_id);
    const std::string on = patch->name.empty() ? "patch " + std::to_string(patch_id) : patch->name;
    const std::vector<ProjectedFace> faces =
        project_faces(model, posed(frame.value, options.pose), std::nullopt, std::nullopt, true);
    if (faces.empty()) {
        r.fail(DiagnosticCode::bad_option, "depth layers: no face of the model faces " + on,
               about_patches({patch_id}));
        return r;
    }
    std::vector<size_t> order(faces.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return faces[a].depth < faces[b].depth; });
    // Splits at the widest gaps wider than min_gap, at most max_layers - 1 of them.
    const double gap = options.min_gap > 0 ? options.min_gap : 0.02 * model.diagonal();
    std::vector<size_t> splits; // a layer starts at order[k] for each k here
    for (size_t k = 1; k < order.size(); ++k)
        if (faces[order[k]].depth - faces[order[k - 1]].depth > gap)
            splits.push_back(k);
    auto width = [&](size_t k) { return faces[order[k]].depth - faces[order[k - 1]].depth; };
    std::stable_sort(splits.begin(), splits.end(),
                     [&](size_t a, size_t b) { return width(a) > width(b); });
    if (splits.size() > size_t(options.max_layers - 1))
        splits.resize(options.max_layers - 1);
    std::sort(splits.begin(), splits.end());
    std::vector<std::vector<size_t>> groups(1);
    for (size_t k = 0, s = 0; k < order.size(); ++k) {
        if (s < splits.size() && splits[s] == k) {
            groups.emplace_back();
            ++s;
        }
        groups.back().push_back(order[k]);
    }
    // Slivers join the neighbour nearer the viewer (the last group joins the one below it).
    auto area_of = [&](const std::vector<size_t>& g) {
        double a = 0;
        for (size_t i : g)
            a += faces[i].area;
        return a;
    };
    double total = 0;
    for (const ProjectedFace& f : faces)
        total += f.area;
    for (size_t k = 0; k < groups.size() && groups.size() > 1;) {
        if (area_of(groups[k]) >= options.min_area_fraction * total) {
            ++k;
            continue;
        }
        const size_t into = k + 1 < groups.size() ? k + 1 : k - 1;
        groups[into].insert(groups[into].end(), groups[k].begin(), groups[k].end());
        groups.erase(groups.begin() + k);
        k = 0;
    }
    for (auto it = groups.rbegin(); it != groups.rend(); ++it) {
        DepthLayer layer;
        std::vector<const ProjectedFace*> members;
        double weighted = 0, area = 0;
        layer.depth_near = faces[it->front()].depth;
        layer.depth_far = faces[it->front()].depth;
        for (size_t i : *it) {
            members.push_back(&faces[i]);
            weighted += faces[i].area * faces[i].depth;
            area += faces[i].area;
            layer.depth_near = std::min(layer.depth_near, faces[i].depth);
            layer.depth_far = std::max(layer.depth_far, faces[i].depth);
        }
        layer.depth = weighted / area;
        std::ostringstream name;
        name << "layer " << r.value.size() + 1 << " of " << on << " at " << layer.depth << " mm";
        layer.silhouette = unite_faces(members, name.str());
        r.value.push_back(std::move(layer));
    }
    return r;
}

} // namespace popup
