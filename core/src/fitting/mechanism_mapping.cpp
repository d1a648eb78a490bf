#include "popup/fitting/mechanism_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>

#include "popup/fitting/mechanism_patches.hpp"

namespace popup {
namespace {

bool has_field(const DesignedMechanism& m, const char* name)
{
    return catalogue_entry(m.kind).field(name) != nullptr;
}

/// Extent along the hinge by its Width (0 for a v-fold: the spine's run is not swept).
double width_of(const DesignedMechanism& m)
{
    return has_field(m, "width") ? m.value("width") : 0.0;
}

struct Areas {
    double total = 0;  // every face of the prism
    double bottom = 0; // the face on the host
    double sides = 0;  // rectangular: faces at s0 and s1; triangular: the two slopes
    double outer = 0;  // rectangular: the face at s1
    double top = 0;    // rectangular: the face at t = height
    double ends = 0;   // the two faces across the hinge
};

Areas areas_of(const Prism& m)
{
    Areas a;
    const double w = m.a1 - m.a0, across = m.s1 - m.s0, h = m.height;
    a.bottom = w * across;
    if (m.kind == Prism::Kind::rectangular) {
        a.top = w * across;
        a.outer = w * h;
        a.sides = 2 * w * h;
        a.ends = 2 * across * h;
        a.total = a.bottom + a.top + a.sides + a.ends;
    } else {
        const double lg = std::hypot(m.s1 - m.apex_s, h), lb = std::hypot(m.apex_s - m.s0, h);
        a.sides = w * (lg + lb);
        a.ends = across * h; // two triangles of area across·h/2
        a.total = a.bottom + a.sides + a.ends;
    }
    return a;
}

} // namespace

std::vector<MechanismKind> mechanism_options(const Prism& m, const PrismHost& host)
{
    using K = MechanismKind;
    if (m.kind == Prism::Kind::rectangular)
        return host.flat ? std::vector<K>{K::box_fold, K::v_fold} : std::vector<K>{K::step_fold};
    return host.flat ? std::vector<K>{K::tent_fold, K::v_fold} : std::vector<K>{};
}

namespace {

/// The prism's run along the hinge, where every kind but the v-fold starts and ends.
void place_along_hinge(Placement1D& q, const Prism& m)
{
    q.offset = m.a0;
    q.width = m.a1 - m.a0;
}

void plan_box(MechanismPlan& p, const Prism& m, const Areas& a)
{
    // At 180° the box is x in [−depth_backdrop, depth_ground], z in [0, height].
    BoxFoldParams& q = p.as<BoxFoldParams>();
    place_along_hinge(q, m);
    q.depth_ground = m.s1;
    q.depth_backdrop = -m.s0;
    q.height = m.height;
    q.panel_pairs = 1;
    q.front = true;
    q.back = true;
    p.principal_area = a.total - a.bottom;
}

void plan_step(MechanismPlan& p, const Prism& m, const PrismHost& host, const Areas& a)
{
    // At 90° the parallelogram is a rectangle: run along the page, rise up the wall. On a box's
    // ground side the page is the host's ground; on its backdrop side the wall is.
    StepFoldParams& q = p.as<StepFoldParams>();
    const bool page_is_ground = host.part != "side_backdrop";
    place_along_hinge(q, m);
    q.run_ground = page_is_ground ? m.s1 : m.height;
    q.run_backdrop = page_is_ground ? m.height : m.s1;
    p.principal_area = a.outer + a.top;
}

void plan_tent(MechanismPlan& p, const Prism& m, const Areas& a)
{
    TentFoldParams& q = p.as<TentFoldParams>();
    place_along_hinge(q, m);
    q.foot = m.s1;
    q.foot_backdrop = -m.s0;
    q.slope = std::hypot(m.s1 - m.apex_s, m.height);
    p.principal_area = a.sides;
}

void plan_v_fold(MechanismPlan& p, const Prism& m, const Areas& a)
{
    // O at the prism's start on the hinge, P over its far end.
    VFoldParams& q = p.as<VFoldParams>();
    const double w = m.a1 - m.a0, d = std::min(m.s1, -m.s0);
    q.offset = m.a0;
    q.run = std::hypot(d, w);
    q.hinge_angle = std::atan2(d, w);
    q.spine = std::hypot(w, m.height);
    q.spine_angle = std::atan2(m.height, w);
    // Its wings stand on the diagonals: half of the faces they stand in front of.
    p.principal_area = 0.5 * a.sides;
}

} // namespace

MechanismPlan plan_mechanism(MechanismKind kind, const Prism& m, const PrismHost& host)
{
    MechanismPlan p;
    static_cast<DesignedMechanism&>(p) = DesignedMechanism::of_kind(kind);
    const Areas a = areas_of(m);
    p.face_area = a.total;
    switch (kind) {
    case MechanismKind::box_fold:
        plan_box(p, m, a);
        break;
    case MechanismKind::step_fold:
        plan_step(p, m, host, a);
        break;
    case MechanismKind::tent_fold:
        plan_tent(p, m, a);
        break;
    case MechanismKind::v_fold:
        plan_v_fold(p, m, a);
        break;
    default:
        throw std::invalid_argument("a prism maps to a box, step, tent or v-fold, not a " +
                                    catalogue_entry(kind).title);
    }
    return p;
}

double coverage_error(const std::vector<MechanismPlan>& plans)
{
    double principal = 0, total = 0;
    for (const auto& p : plans) {
        principal += p.principal_area;
        total += p.face_area;
    }
    return total > 0 ? 1.0 - principal / total : 1.0;
}

namespace {

/// Per prism: how many samples the search assigned to it, and for each of its options the sum
/// of their distances to that mechanism's patches at the design state.
struct OptionDistances {
    std::vector<int> samples;
    std::vector<std::vector<double>> sum;
};

OptionDistances option_distances(const RansacResult& fit, const SurfaceSamples& samples,
                                 const std::vector<std::vector<MechanismKind>>& options)
{
    const size_t n = fit.prisms.size();
    if (fit.owner.size() != samples.points.size())
        throw std::invalid_argument(
            "map_mechanisms: fit.owner has " + std::to_string(fit.owner.size()) + " entries for " +
            std::to_string(samples.points.size()) + " samples: it needs one per sample");
    std::vector<std::vector<Vec3>> owned(n);
    for (size_t i = 0; i < fit.owner.size(); ++i) {
        const int k = fit.owner[i];
        if (k < -1 || k >= int(n))
            throw std::invalid_argument("map_mechanisms: fit.owner[" + std::to_string(i) +
                                        "] = " + std::to_string(k) + ", must be -1 or in [0, " +
                                        std::to_string(int(n) - 1) + "] (the prisms' indices)");
        if (k >= 0)
            owned[k].push_back(host_coordinates(fit.hosts[fit.prisms[k].host], samples.points[i]));
    }
    OptionDistances d;
    d.samples.resize(n);
    d.sum.resize(n);
    for (size_t k = 0; k < n; ++k) {
        d.samples[k] = int(owned[k].size());
        const Prism& m = fit.prisms[k];
        const PrismHost& h = fit.hosts[m.host];
        for (MechanismKind kind : options[k]) {
            const std::vector<HostPolygon> patches = design_patches(plan_mechanism(kind, m, h), h);
            double sum = 0;
            for (const Vec3& q : owned[k])
                sum += distance_to_patches(q, patches);
            d.sum[k].push_back(sum);
        }
    }
    return d;
}

} // namespace

Mapping map_mechanisms(const RansacResult& fit, const SurfaceSamples& samples)
{
    Mapping best;
    const size_t n = fit.prisms.size();
    std::vector<std::vector<MechanismKind>> options(n);
    for (size_t i = 0; i < n; ++i)
        options[i] = mechanism_options(fit.prisms[i], fit.hosts[fit.prisms[i].host]);
    const OptionDistances distances = option_distances(fit, samples, options);
    int owned = 0;
    for (size_t k = 0; k < n; ++k)
        owned += options[k].empty() ? 0 : distances.samples[k];
    // Sums closer than a nanometre per sample are a tie (docs/MATH.md, "Mapping by distance").
    const double tie = 1e-9 * (1 + owned);
    // Exhaustive: few primitives (max_mechanisms), at most two options each.
    std::vector<int> choice(n, 0);
    double best_distance = 1e300, best_error = 2.0;
    std::vector<int> best_choice;
    std::function<void(size_t)> visit = [&](size_t i) {
        if (i == n) {
            std::vector<MechanismPlan> plans;
            double distance = 0;
            for (size_t k = 0; k < n; ++k) {
                if (options[k].empty())
                    continue;
                const Prism& m = fit.prisms[k];
                const PrismHost& h = fit.hosts[m.host];
                if (h.parent >= 0 &&
                    (options[h.parent].empty() ||
                     options[h.parent][choice[h.parent]] != MechanismKind::box_fold))
                    return; // stands on a part only a box fold offers
                plans.push_back(plan_mechanism(options[k][choice[k]], m, h));
                distance += distances.sum[k][choice[k]];
            }
            const double e = coverage_error(plans);
            if (distance < best_distance - tie ||
                (distance <= best_distance + tie && e < best_error - 1e-12)) {
                best_distance = distance;
                best_error = e;
                best_choice = choice;
            }
            return;
        }
        const int count = std::max<int>(1, int(options[i].size()));
        for (int c = 0; c < count; ++c) {
            choice[i] = c;
            visit(i + 1);
        }
    };
    visit(0);
    if (best_choice.empty())
        return best;
    best.coverage_error = best_error;
    best.sample_distance = owned > 0 ? best_distance / owned : 0.0;
    std::map<MechanismKind, int> counters;
    std::vector<int> plan_of(n, -1);
    for (size_t k = 0; k < n; ++k) {
        if (options[k].empty()) {
            best.unmapped.push_back(int(k));
            continue;
        }
        const Prism& m = fit.prisms[k];
        const PrismHost& h = fit.hosts[m.host];
        MechanismPlan p = plan_mechanism(options[k][best_choice[k]], m, h);
        p.prism = int(k);
        p.name = catalogue_entry(p.kind).short_name + std::to_string(++counters[p.kind]);
        p.samples = distances.samples[k];
        p.sample_distance = p.samples ? distances.sum[k][best_choice[k]] / p.samples : 0.0;
        if (h.parent < 0) {
            p.host = "central fold";
        } else {
            p.parent = plan_of[h.parent];
            p.host = best.plans[p.parent].name + "." + h.part;
        }
        plan_of[k] = int(best.plans.size());
        best.plans.push_back(p);
    }
    return best;
}

std::vector<std::pair<std::string, std::string>>
refit_for_foldability(std::vector<MechanismPlan>& plans, double min_part)
{
    std::vector<std::pair<std::string, std::string>> changes;
    auto sweep = [](const MechanismPlan& p) {
        const double a0 = p.offset(), a1 = a0 + width_of(p);
        if (p.kind != MechanismKind::box_fold)
            return std::make_pair(a0, a1);
        const BoxFoldParams& q = p.as<BoxFoldParams>();
        return std::make_pair(a0 - (q.front ? q.depth_ground : 0.0),
                              a1 + (q.back ? q.depth_ground : 0.0));
    };
    for (size_t i = 0; i < plans.size(); ++i)
        for (size_t j = 0; j < plans.size(); ++j) {
            if (i == j || plans[i].host != plans[j].host || plans[i].offset() > plans[j].offset())
                continue;
            MechanismPlan& first = plans[i];
            MechanismPlan& second = plans[j];
            if (sweep(first).second <= sweep(second).first)
                continue;
            // Thesis §4.2.2: the end panels facing each other come off first.
            if (first.kind == MechanismKind::box_fold && first.as<BoxFoldParams>().back &&
                first.as<BoxFoldParams>().front) {
                first.as<BoxFoldParams>().back = false;
                changes.push_back({first.name, "trimmed its back panels: closed, they would "
                                               "run into " +
                                                   second.name});
            }
            if (sweep(first).second > sweep(second).first &&
                second.kind == MechanismKind::box_fold && second.as<BoxFoldParams>().front &&
                second.as<BoxFoldParams>().back) {
                second.as<BoxFoldParams>().front = false;
                changes.push_back({second.name, "trimmed its front panels: closed, they would "
                                                "run into " +
                                                    first.name});
            }
            const double overlap = sweep(first).second - sweep(second).first;
            if (overlap > 0) {
                const bool has_width = has_field(second, "width");
                const double keep = has_width ? width_of(second) - overlap : 0.0;
                if (has_width && keep > 0 && keep >= min_part) {
                    second.set_value("offset", second.offset() + overlap);
                    second.set_value("width", keep);
                    std::ostringstream why;
                    why << "shortened by " << overlap << " mm along its hinge: it overlapped "
                        << first.name;
                    changes.push_back({second.name, why.str()});
                }
            }
        }
    return changes;
}

namespace {

// What a host offers a mechanism standing on it (mm): its length along the hinge and the depth
// on each side (for a box's side pairs: the wall's height on one side, the page on the other).
struct HostRoom {
    double length = 0, ground = 0, backdrop = 0;
};

HostRoom room_offered(const MechanismPlan& box, const HostRoom& its_host, const std::string& part)
{
    const BoxFoldParams& q = box.as<BoxFoldParams>();
    if (part == "top")
        return {q.width, q.depth_ground, q.depth_backdrop};
    if (part == "side_ground")
        return {q.width, its_host.ground - q.depth_ground, q.height};
    return {q.width, q.height, its_host.backdrop - q.depth_backdrop}; // side_backdrop
}

} // namespace

void keep_inside_ranges(std::vector<MechanismPlan>& plans, double card_width, double card_depth,
                        double margin)
{
    std::vector<HostRoom> host_of(plans.size());
    for (size_t k = 0; k < plans.size(); ++k) {
        MechanismPlan& p = plans[k];
        HostRoom host{card_width, card_depth, card_depth};
        if (p.parent >= 0) {
            const std::string part = p.host.substr(p.host.find('.') + 1);
            host = room_offered(plans[p.parent], host_of[p.parent], part);
        }
        // Along the hinge: [margin, length − margin].
        const bool has_width = has_field(p, "width");
        const double span = std::min(p.extent(), host.length - 2 * margin);
        if (has_width)
            p.set_value("width", span);
        p.set_value("offset", std::clamp(p.offset(), margin, host.length - margin - span));
        // Across: below each side's depth.
        for (const ParameterField& f : catalogue_entry(p.kind).fields) {
            if (f.bound == HostBound::ground_depth)
                f.set(p.params, std::min(f.get(p.params), host.ground - margin));
            if (f.bound == HostBound::backdrop_depth)
                f.set(p.params, std::min(f.get(p.params), host.backdrop - margin));
        }
        host_of[k] = host;
    }
}

} // namespace popup
