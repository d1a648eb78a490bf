#include "popup/mechanisms/horizontal_translation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

namespace {
constexpr double slit_bridge = 5.0; // mm of paper beyond each end of the slit
} // namespace

Vec2 horizontal_translation_tip(const HorizontalTranslationParams& p, double opening)
{
    const Vec2 nose = step_nose(p, opening);
    return p.reach * nose / nose.norm();
}

Result<MechanismParts> add_horizontal_translation(Scaffold& scaffold, const BasePatchPair& host,
                                                  const HorizontalTranslationParams& p,
                                                  const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_flat_host(name, host, "a horizontal translation", e);
    check_placement(name, host, p, e);
    check_run(e, name, "RunGround", p.run_ground, host.ground_depth, "ground");
    if (!(p.run_backdrop > 0 && p.run_backdrop < p.run_ground)) {
        std::ostringstream m;
        m << "> 0 and < RunGround (" << p.run_ground
          << " mm): the nose must stand off the hinge on the ground side for M to pass it";
        range_error(e, name, "RunBackdrop", p.run_backdrop, "mm", m.str());
    }
    if (e.empty()) {
        const double through = p.run_ground - p.run_backdrop;
        if (!(p.reach > through && p.reach <= host.ground_depth)) {
            std::ostringstream m;
            m << "> " << through
              << " mm (RunGround − RunBackdrop, to pass the slit) and <= " << host.ground_depth
              << " mm (the depth of the host's ground)";
            range_error(e, name, "Reach", p.reach, "mm", m.str());
        }
    }
    if (e.empty())
        check_part_sizes(scaffold, name,
                         {{"Width", p.width},
                          {"RunGround", p.run_ground},
                          {"RunBackdrop", p.run_backdrop},
                          {"Reach", p.reach}},
                         e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    // The step fold, then M lying on the ground from the hinge to P through the nose line. The
    // builder starts first, so a failed check takes the step fold out again too.
    MechanismBuilder m(scaffold, host, name);
    Result<MechanismParts> step = add_step_fold(scaffold, host, p, name);
    if (!step.ok)
        return step;
    MechanismParts parts = step.value;
    // M and its slit stop short of the step's ends: the paper left there keeps the riser and
    // the tread one piece (a slit as long as the nose would cut them apart).
    const double bridge = std::min(slit_bridge, 0.2 * p.width);
    const double y0 = p.offset + bridge, y1 = p.offset + p.width - bridge;
    const double a = p.run_ground, b = p.run_backdrop;
    const int M = m.patch({{0, y0, 0}, {p.reach, y0, 0}, {p.reach, y1, 0}, {0, y1, 0}},
                          PatchRole::other, "M");
    // Flat on the ground at the design state; it lifts with the nose.
    m.tab(host.ground, M, {0, y0, 0}, {0, y1, 0}, FoldDirection::valley);
    m.sweeps(p.offset, p.offset + p.width);
    Result<MechanismParts> added = m.finish();
    if (!added.ok)
        return added;
    Slit slit;
    slit.patch_cut = parts.patches[0]; // the riser; the slit runs along its nose edge
    slit.patch_through = M;
    slit.from = m.world({a - b, y0, 0});
    slit.to = m.world({a - b, y1, 0});
    for (const Slit& other : scaffold.slits)
        slit.id = std::max(slit.id, other.id + 1);
    scaffold.slits.push_back(slit);
    parts.patches.insert(parts.patches.end(), added.value.patches.begin(),
                         added.value.patches.end());
    r.value = parts;
    return r;
}

} // namespace popup
