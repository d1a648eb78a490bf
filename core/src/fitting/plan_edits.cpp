#include "plan_edits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace popup {

std::vector<int> standing_on(const std::vector<MechanismPlan>& plans, size_t i)
{
    std::vector<bool> above(plans.size(), false);
    above[i] = true;
    std::vector<int> found;
    for (size_t k = i + 1; k < plans.size(); ++k) // plans come hosts first
        if (plans[k].parent >= 0 && above[size_t(plans[k].parent)]) {
            above[k] = true;
            found.push_back(int(k));
        }
    return found;
}

namespace {

bool has_width(const MechanismPlan& p)
{
    return catalogue_entry(p.kind).field("width") != nullptr;
}

/// Every length of `p` times `factor`, its offset too unless `keep_middle` (then it moves so the
/// middle of its extent stays). False when a length at least `min_part` would fall below it.
bool scale_lengths(MechanismPlan& p, double factor, bool keep_middle, double min_part)
{
    const double middle = p.offset() + p.extent() / 2;
    for (const ParameterField& f : catalogue_entry(p.kind).fields) {
        if (f.unit != FieldUnit::length)
            continue;
        const double v = f.get(p.params);
        if (f.name != "offset" && v >= min_part && v * factor < min_part)
            return false;
        if (f.name != "offset" || !keep_middle)
            f.set(p.params, v * factor);
    }
    if (keep_middle && catalogue_entry(p.kind).field("offset"))
        p.set_value("offset", middle - p.extent() / 2);
    return true;
}

/// Cuts plan `k` to [lo, hi] along its host's hinge; what stands directly on it (on pairs that
/// start where it starts, as a box's do) keeps its place and is cut in turn.
bool cut_plan(PlanEdit& e, size_t k, double lo, double hi, double min_part, double margin)
{
    MechanismPlan& p = e.plans[k];
    const double a = p.offset(), b = a + p.extent();
    const double a2 = std::max(a, lo), b2 = std::min(b, hi);
    if (!has_width(p) || b2 - a2 < std::max(min_part, margin))
        return false;
    p.set_value("offset", a2);
    p.set_value("width", b2 - a2);
    for (size_t c = k + 1; c < e.plans.size(); ++c) {
        if (e.plans[c].parent != int(k))
            continue;
        MechanismPlan& child = e.plans[c];
        if (catalogue_entry(child.kind).field("offset"))
            child.set_value("offset", child.offset() - (a2 - a));
        PlanEdit trial = e;
        if (cut_plan(trial, c, margin, b2 - a2 - margin, min_part, margin))
            e = std::move(trial);
        e.carried.push_back(int(c));
    }
    return true;
}

bool fits_depths(const MechanismPlan& p, const BasePatchPair& host, double margin)
{
    for (const ParameterField& f : catalogue_entry(p.kind).fields) {
        if (f.bound == HostBound::ground_depth && f.get(p.params) > host.ground_depth - margin)
            return false;
        if (f.bound == HostBound::backdrop_depth && f.get(p.params) > host.backdrop_depth - margin)
            return false;
    }
    return true;
}

std::string shown(const ParameterField& f, double v)
{
    std::ostringstream s;
    s.precision(4);
    switch (f.unit) {
    case FieldUnit::length:
        s << v << " mm";
        break;
    case FieldUnit::angle:
        s << v * 180 / M_PI << "°";
        break;
    case FieldUnit::flag:
        s << (v != 0 ? "yes" : "no");
        break;
    case FieldUnit::count:
        s << v;
        break;
    }
    return s.str();
}

} // namespace

std::optional<PlanEdit> scale_about_place(const std::vector<MechanismPlan>& plans, size_t i,
                                          double factor, double min_part)
{
    PlanEdit e{plans, {}};
    if (!scale_lengths(e.plans[i], factor, true, min_part))
        return std::nullopt;
    for (int k : standing_on(plans, i)) {
        if (!scale_lengths(e.plans[size_t(k)], factor, false, min_part))
            return std::nullopt;
        e.carried.push_back(k);
    }
    return e;
}

std::optional<PlanEdit> cut_along_hinge(const std::vector<MechanismPlan>& plans, size_t i,
                                        double lo, double hi, double min_part, double margin)
{
    PlanEdit e{plans, {}};
    if (!cut_plan(e, i, lo, hi, min_part, margin))
        return std::nullopt;
    return e;
}

std::optional<PlanEdit> move_to_pair(const std::vector<MechanismPlan>& plans, size_t i,
                                     const BasePatchPair& from, const BasePatchPair& to,
                                     int new_parent, double margin)
{
    const double along = from.axis.dot(to.axis);
    if (std::abs(std::abs(along) - 1) > 1e-6 || std::abs(from.opening - to.opening) > 1e-6)
        return std::nullopt;
    PlanEdit e{plans, {}};
    MechanismPlan& p = e.plans[i];
    const double extent = p.extent();
    const double start = (from.to_world(0, p.offset(), 0) - to.origin).dot(to.axis);
    const double offset = along > 0 ? start : start - extent;
    if (offset < -margin || offset + extent > to.length + margin ||
        extent > to.length - 2 * margin || !fits_depths(p, to, margin))
        return std::nullopt;
    if (catalogue_entry(p.kind).field("offset"))
        p.set_value("offset", std::clamp(offset, margin, to.length - margin - extent));
    p.host = to.name;
    p.parent = new_parent;
    return e;
}

std::string describe_changes(const MechanismPlan& before, const MechanismPlan& after)
{
    std::string out;
    for (const ParameterField& f : catalogue_entry(before.kind).fields) {
        const double a = f.get(before.params), b = f.get(after.params);
        if (std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)))
            continue;
        out += (out.empty() ? "" : ", ") + f.property + " " + shown(f, a) + " → " + shown(f, b);
    }
    return out;
}

} // namespace popup
