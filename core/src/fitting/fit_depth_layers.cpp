#include "popup/fitting/fit_depth_layers.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <sstream>

#include "layer_footprint.hpp"
#include "outline_support.hpp"
#include "popup/fitting/depth_layers.hpp"
#include "popup/fitting/fit_metrics.hpp"
#include "popup/simulation/check_validity.hpp"

namespace popup {

using layer_footprint::cut_part;
using layer_footprint::Footprint;
using layer_footprint::footprint;
using layer_footprint::patch_named;
using outline_support::first_error;
using outline_support::placed;
namespace {

std::string mm(double x)
{
    std::ostringstream o;
    o.precision(3);
    o << std::fixed << x;
    return o.str();
}

/// The next free name with this prefix (S, B) among the design's mechanisms.
std::string free_name(const std::string& prefix, const std::set<std::string>& taken)
{
    for (int k = 1;; ++k)
        if (!taken.count(prefix + std::to_string(k)))
            return prefix + std::to_string(k);
}

FitMetricsOptions metric_options(const DepthLayerFitOptions& o)
{
    FitMetricsOptions fo;
    fo.samples = o.metric_samples;
    fo.seed = o.seed;
    fo.hausdorff_error = 0.1; // only the sampled mean is used
    fo.volume_cells = 2;
    return fo;
}

/// Mean distance from the model's surface to the pop-up at 180° (fit_metrics), mm.
std::optional<double> mean_distance(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                                    const Scaffold& s, const DepthLayerFitOptions& o)
{
    const Result<FitMetrics> m = fit_metrics(model, model_to_card, s, {}, metric_options(o));
    if (!m.ok)
        return std::nullopt;
    return m.value.model_to_popup_mm.mean;
}

/// One face of one box: which patch it is, which pair a layer stands on, how it is built.
struct Face {
    std::string label; ///< "front", "back" or "top"
    std::string patch; ///< the patch clustered (B1.L, B1.TG)
    std::string pair;  ///< what a layer stands on (B1.side_ground, B1.top)
};

/// A trial layer built on a copy of the design: the mechanism, its cut part's profiles.
struct Built {
    Scaffold scaffold;
    FittedMechanism mechanism;
    std::vector<FittedProfile> profiles;
};

/// The triangles of `model` whose centroid lies over the pair's room: [0, length] along its
/// hinge, [lo, hi] along `across` (the vertices are kept whole; unused ones do no harm).
ModelMesh in_front_of(const ModelMesh& model, const BasePatchPair& pair, const Vec3& across,
                      double lo, double hi)
{
    ModelMesh out;
    out.source = model.source;
    out.vertices = model.vertices;
    for (const auto& t : model.triangles) {
        const Vec3 c = (model.vertices[size_t(t[0])] + model.vertices[size_t(t[1])] +
                        model.vertices[size_t(t[2])]) /
                           3.0 -
                       pair.origin;
        const double a = c.dot(pair.axis), b = c.dot(across);
        if (a >= 0 && a <= pair.length && b >= lo && b <= hi)
            out.triangles.push_back(t);
    }
    return out;
}

/// The first mechanism of `fitted` or `added` standing on `pair` whose span along its hinge
/// overlaps [from, to], or empty.
std::string occupant(const std::vector<FittedMechanism>& fitted,
                     const std::vector<FittedMechanism>& added, const std::string& pair,
                     double from, double to)
{
    for (const auto* list : {&fitted, &added})
        for (const FittedMechanism& m : *list) {
            if (m.host != pair)
                continue;
            const double a0 = m.offset();
            if (a0 < to && from < a0 + m.extent())
                return m.name;
        }
    return {};
}

/// The parts of the new mechanism `name` whose plane is parallel to `face` (the patch clustered).
std::vector<std::string> facing_parts(const Scaffold& s, const std::string& name, const Patch& face,
                                      bool wall)
{
    Patch f = face;
    f.derive_frame();
    std::vector<std::string> out;
    for (const std::string& part :
         wall ? std::vector<std::string>{"riser", "tread"} : std::vector<std::string>{"TG", "TB"}) {
        const Patch* p = patch_named(s, name + "." + part);
        if (!p)
            continue;
        Patch q = *p;
        q.derive_frame();
        if (std::abs(q.normal.dot(f.normal)) > 1.0 - 1e-6)
            out.push_back(part);
    }
    return out;
}

/// A box's face as the ground of its layers: the pair a layer stands on, the direction across
/// its hinge in the world and the room it offers there, and the face's layers.
struct FaceGround {
    Face face;
    BasePatchPair pair;
    Patch face_patch; ///< as it was before any layer of it was kept
    ProfileFrame frame;
    Vec3 across = Vec3::UnitX();
    bool wall = false;
    bool wall_is_backdrop = false;
    double wall_height = 0.0, page_room = 0.0;
    double lo = 0.0, hi = 0.0; ///< the room along `across`
    std::vector<DepthLayer> layers;
};

/// `face` of a box in `s` with its layers, or none when the design has no such patch or pair, or
/// no face of the model faces it there.
std::optional<FaceGround> face_ground(const Face& face, const Scaffold& s,
                                      const std::map<std::string, BasePatchPair>& pairs,
                                      const ModelMesh& in_card)
{
    const Patch* patch = patch_named(s, face.patch);
    const auto pair_it = pairs.find(face.pair);
    if (!patch || pair_it == pairs.end())
        return std::nullopt;
    const BasePatchPair& pair = pair_it->second;
    const Patch face_patch = *patch; // s changes as layers are kept
    const int patch_id = face_patch.id;
    // Across the pair's hinge in the world: up the box's wall (L is a side pair's
    // backdrop, R its ground), or the top's ground side. A wall layer is a step on the
    // side pair; a top layer a box on the top pair.
    const bool wall = face.label != "top";
    const bool wall_is_backdrop = face.label == "front";
    const Vec2 bd = wall_is_backdrop ? pair.backdrop_direction() : pair.ground_direction();
    const Vec3 across = (bd.x() * pair.x_axis() + bd.y() * pair.up).normalized();
    const double wall_height = wall_is_backdrop ? pair.backdrop_depth : pair.ground_depth;
    const double page_room = wall_is_backdrop ? pair.ground_depth : pair.backdrop_depth;
    const double lo = wall ? 0.0 : -pair.backdrop_depth;
    const double hi = wall ? wall_height : pair.ground_depth;
    // Only the model in front of the pair's room is clustered: another part of the
    // model at a similar depth elsewhere must not pull a layer's depth.
    const Result<ProfileFrame> frame = profile_frame(s, patch_id);
    DepthLayerOptions dlo;
    dlo.min_gap = 0.02 * in_card.diagonal();
    const Result<std::vector<DepthLayer>> layers =
        depth_layers(in_front_of(in_card, pair, across, lo, hi), s, patch_id, dlo);
    if (!frame.ok || !layers.ok)
        return std::nullopt; // no face of the model faces it there: nothing to layer
    return FaceGround{
        face,        pair,      face_patch, frame.value, across,      wall, wall_is_backdrop,
        wall_height, page_room, lo,         hi,          layers.value};
}

/// What every layer's trial reads besides its face.
struct LayerRules {
    const ModelMesh& model;
    const Eigen::Matrix4d& model_to_card;
    const std::vector<FittedMechanism>& mechanisms; ///< the fitted design's
    const DepthLayerFitOptions& options;
    const ValidityOptions& vo;
    double min_part = 0.0;
    double margin = 0.0; ///< parameters stay this far inside their generator's ranges (mm)
};

/// The nested mechanism for a layer of footprint `f`, strictly inside its generator's ranges.
FittedMechanism layer_mechanism(const FittedMechanism& box, const FaceGround& g,
                                const DepthLayer& layer, const Footprint& f, double margin,
                                const std::set<std::string>& taken)
{
    const Face& face = g.face;
    const BasePatchPair& pair = g.pair;
    const bool wall = g.wall, wall_is_backdrop = g.wall_is_backdrop;
    const double width = f.hi.x() - f.lo.x();
    const double rise = f.hi.y();
    const double w = std::min(width, pair.length - 2 * margin);
    const double offset = std::clamp(f.lo.x(), margin, pair.length - margin - w);
    FittedMechanism m;
    if (wall) {
        // Along the page: the layer's depth; up the wall: its top.
        static_cast<DesignedMechanism&>(m) =
            DesignedMechanism::of_kind(MechanismKind::step_fold, free_name("S", taken), face.pair);
        StepFoldParams& q = m.as<StepFoldParams>();
        const double run = std::min(layer.depth, g.page_room - margin);
        const double up = std::min(rise, g.wall_height - margin);
        q.offset = offset;
        q.width = w;
        q.run_ground = wall_is_backdrop ? run : up;
        q.run_backdrop = wall_is_backdrop ? up : run;
    } else {
        static_cast<DesignedMechanism&>(m) =
            DesignedMechanism::of_kind(MechanismKind::box_fold, free_name("B", taken), face.pair);
        BoxFoldParams& q = m.as<BoxFoldParams>();
        q.offset = offset;
        q.width = w;
        q.depth_ground = std::min(f.hi.y(), pair.ground_depth - margin);
        q.depth_backdrop = std::min(-f.lo.y(), pair.backdrop_depth - margin);
        q.height = layer.depth;
        q.panel_pairs = 1;
        q.front = true;
        q.back = true;
    }
    m.primitive = face.label + " depth layer of " + box.name + " at " + mm(layer.depth) + " mm";
    return m;
}

/// `trial.mechanism` built on `trial.scaffold` and its parts parallel to the face cut to the
/// layer's footprint; empty, or why not.
std::string build_layer(const FaceGround& g, const Footprint& f, Built& trial)
{
    const BasePatchPair& pair = g.pair;
    const FittedMechanism& m = trial.mechanism;
    const Result<MechanismParts> added = add_mechanism(trial.scaffold, pair, m);
    if (!added.ok)
        return "its generator refused it: " + first_error(added.diagnostics, "out of range");
    // The parts parallel to the face (what the viewer sees of the layer) take its
    // silhouette: a step's riser on a front, its tread on a back (on the backdrop
    // side pair the wall is the ground), a box's top.
    for (const std::string& part : facing_parts(trial.scaffold, m.name, g.face_patch, g.wall)) {
        Result<std::optional<FittedProfile>> cut =
            cut_part(trial.scaffold, m.name, part, f, pair, g.across);
        if (!cut.ok)
            return "its " + part + " could not take the layer's outline: " +
                   first_error(cut.diagnostics, "refused");
        if (cut.value)
            trial.profiles.push_back(*cut.value);
    }
    return {};
}

/// Tries `layer` of `g` as a nested mechanism: kept into `out` while the design stays valid and
/// the model-to-pop-up mean distance drops (`measure_baseline` measures the design's once),
/// dropped otherwise; either way reported in out.layers and out.repairs.
void try_layer(const FittedMechanism& box, const FaceGround& g, const DepthLayer& layer,
               const LayerRules& rules, const std::function<bool()>& measure_baseline,
               std::set<std::string>& taken, DepthLayerOutcome& out)
{
    const Face& face = g.face;
    const BasePatchPair& pair = g.pair;
    const bool wall = g.wall;
    const double min_part = rules.min_part;
    FittedDepthLayer report;
    report.box = box.name;
    report.face = face.label;
    report.depth = layer.depth;
    auto drop = [&](const std::string& why) {
        report.reason = why;
        out.repairs.push_back(
            {report.mechanism.empty() ? box.name : report.mechanism, "layer dropped",
             face.label + " layer " + mm(layer.depth) + " mm proud of " + face.patch + ": " + why});
        out.layers.push_back(report);
    };
    const std::optional<Footprint> f =
        footprint(layer.silhouette, g.frame, pair, g.across, g.lo, g.hi);
    if (!f) {
        drop("its silhouette lies outside what " + face.pair + " offers");
        return;
    }
    report.area = f->area;
    // What already stands on the pair there models that part of the model (a
    // fitted primitive, or an earlier layer): a layer there would duplicate it.
    const std::string occupied =
        occupant(rules.mechanisms, out.mechanisms, face.pair, f->lo.x(), f->hi.x());
    if (!occupied.empty()) {
        drop(face.pair + " already carries " + occupied + " along " + mm(f->lo.x()) + " to " +
             mm(f->hi.x()) + " mm of its hinge");
        return;
    }
    const double width = f->hi.x() - f->lo.x();
    const double rise = f->hi.y();
    std::ostringstream small;
    if (width < min_part)
        small << "its width along the hinge " << mm(width) << " mm";
    else if (layer.depth < min_part)
        small << "it stands only " << mm(layer.depth) << " mm proud";
    else if (wall && rise < min_part)
        small << "its top is only " << mm(rise) << " mm up the wall";
    else if (!wall && (f->hi.y() < min_part || -f->lo.y() < min_part))
        small << "it reaches " << mm(f->hi.y()) << " mm to the ground side and " << mm(-f->lo.y())
              << " mm to the backdrop side of " << face.pair << "'s fold (a box fold needs both)";
    if (!small.str().empty()) {
        drop(small.str() + ", below min_part_mm = " + mm(min_part) + " mm");
        return;
    }
    const FittedMechanism m = layer_mechanism(box, g, layer, *f, rules.margin, taken);
    report.mechanism = m.name;
    Built trial{out.scaffold, m, {}};
    const std::string refused = build_layer(g, *f, trial);
    if (!refused.empty()) {
        drop(refused);
        return;
    }
    const ValidityReport check = check_validity(trial.scaffold, rules.vo);
    if (!check.valid()) {
        drop("the validity check failed with it: " + first_error(check.diagnostics, "not valid"));
        return;
    }
    if (!measure_baseline()) {
        drop("the design's distance to the model could not be measured");
        return;
    }
    const std::optional<double> after =
        mean_distance(rules.model, rules.model_to_card, trial.scaffold, rules.options);
    report.mean_before_mm = out.mean_after_mm;
    report.mean_after_mm = after ? *after : 0.0;
    if (!after || !(*after < out.mean_after_mm)) {
        drop("the model-to-pop-up mean distance would go from " + mm(out.mean_after_mm) + " to " +
             (after ? mm(*after) : "unmeasured") + " mm");
        return;
    }
    report.kept = true;
    report.reason = "valid, and the model-to-pop-up mean distance drops from " +
                    mm(out.mean_after_mm) + " to " + mm(*after) + " mm";
    out.repairs.push_back({m.name, "layer kept",
                           face.label + " layer " + mm(layer.depth) + " mm proud of " + face.patch +
                               ": " + report.reason});
    out.layers.push_back(report);
    out.mean_after_mm = *after;
    out.scaffold = std::move(trial.scaffold);
    out.mechanisms.push_back(m);
    for (const FittedProfile& fp : trial.profiles)
        out.profiles.push_back(fp);
    taken.insert(m.name);
}

} // namespace

Result<DepthLayerOutcome>
fit_depth_layers(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                 const Scaffold& scaffold, const std::vector<FittedMechanism>& mechanisms,
                 const std::map<std::string, BasePatchPair>& pairs,
                 const DepthLayerFitOptions& options, const CancelFlag* cancel)
{
    Result<DepthLayerOutcome> result;
    auto bad = [&](const std::string& option, double value, const std::string& range) {
        std::ostringstream m;
        m << "depth layers: " << option << " = " << value << ", must be " << range;
        result.fail(DiagnosticCode::bad_option, m.str(), about_parameter(option));
    };
    if (!(options.min_part_mm >= 0 && std::isfinite(options.min_part_mm)))
        bad("min_part_mm", options.min_part_mm, "a length >= 0 mm");
    if (!(options.metric_samples >= 100 && options.metric_samples <= 10000000))
        bad("metric_samples", options.metric_samples, "100 to 10000000");
    if (!std::isfinite(options.range_margin))
        bad("range_margin", options.range_margin, "a finite length in mm (<= 0 for the default)");
    if (!result.ok)
        return result;
    DepthLayerOutcome& out = result.value;
    out.scaffold = scaffold;
    const ModelMesh in_card = placed(model, model_to_card);
    FitMetricsOptions fo = metric_options(options);
    // The design's mean distance, measured once and only when a layer gets that far: most
    // boxes have no layer standing proud, and the measure is the stage's dearest step.
    enum class Baseline { unmeasured, measured, failed } baseline = Baseline::unmeasured;
    auto measure_baseline = [&] {
        if (baseline != Baseline::unmeasured)
            return baseline == Baseline::measured;
        const Result<FitMetrics> measured = fit_metrics(model, model_to_card, scaffold, {}, fo);
        if (!measured.ok) { // nothing to compare with: no layer can show it helps
            for (const Diagnostic& d : measured.diagnostics)
                result.diagnostics.push_back(Diagnostic::warning(
                    d.code, "depth layers not tried: " + d.message, about_patches(d.patches)));
            baseline = Baseline::failed;
            return false;
        }
        out.mean_before_mm = out.mean_after_mm = measured.value.model_to_popup_mm.mean;
        baseline = Baseline::measured;
        return true;
    };
    std::set<std::string> taken;
    for (const FittedMechanism& m : mechanisms)
        taken.insert(m.name);
    const double min_part = options.min_part_mm;
    const double margin =
        options.range_margin > 0 ? options.range_margin : 1e-6 * std::max(1.0, in_card.diagonal());
    ValidityOptions vo;
    vo.cancel = cancel;
    const LayerRules rules{model, model_to_card, mechanisms, options, vo, min_part, margin};
    for (const FittedMechanism& box : mechanisms) {
        if (box.kind != MechanismKind::box_fold)
            continue;
        for (const Face& face : {Face{"front", box.name + ".L", box.name + ".side_ground"},
                                 Face{"back", box.name + ".R", box.name + ".side_backdrop"},
                                 Face{"top", box.name + ".TG", box.name + ".top"}}) {
            stop_if_cancelled(cancel, "depth layers");
            const std::optional<FaceGround> g = face_ground(face, out.scaffold, pairs, in_card);
            if (!g)
                continue;
            // The face's own layer is the one nearest its plane; a layer counts as standing
            // proud when its faces all lie in front of that one's.
            const std::vector<DepthLayer>& all = g->layers;
            size_t own = 0;
            for (size_t k = 1; k < all.size(); ++k)
                if (std::abs(all[k].depth) < std::abs(all[own].depth))
                    own = k;
            for (size_t k = 0; k < all.size(); ++k) {
                if (k == own || all[k].depth_near <= all[own].depth_far)
                    continue; // the face itself, or behind it: nothing stands there
                try_layer(box, *g, all[k], rules, measure_baseline, taken, out);
            }
        }
    }
    return result;
}

} // namespace popup
