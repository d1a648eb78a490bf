#include "motion_outlines.hpp"

#include <algorithm>

#include "popup/fitting/fit_outlines.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup::motion {

namespace {

/// The errors of the default sheets of `s` (a glue tab with no room, a piece that falls apart),
/// or the layout's own when it fails: an outline must not add one (issue 26: a profiled platform
/// left its support's glue tab no room, and `popup animate` exited 1 on the demo's figure).
std::size_t sheet_errors(const Scaffold& s)
{
    const Result<SheetSet> laid = layout_sheets(s, SheetOptions{});
    const Diagnostics& found = laid.ok ? laid.value.diagnostics : laid.diagnostics;
    return std::size_t(std::count_if(found.begin(), found.end(), [](const Diagnostic& d) {
        return d.severity == Severity::error;
    }));
}

} // namespace

void outline_motion(const Animation& animation, MotionResult& r, const CancelFlag* cancel)
{
    if (animation.mesh.vertices.empty() || animation.mesh.triangles.empty()) {
        r.diagnostics.push_back(Diagnostic::warning(
            DiagnosticCode::empty_model,
            "the animation " + animation.source +
                " has no skinned mesh (a BVH skeleton or trajectory JSON): the patches keep "
                "their generated shapes, without the character's outline"));
        return;
    }
    const std::vector<PrintedPart> printed = printed_parts(animation, r);
    std::size_t errors = sheet_errors(r.scaffold);
    for (const PrintedPart& limb : printed_parts(animation, r)) {
        if (limb.mechanism.empty())
            continue; // the body: printed on the pages, outlined by nothing
        std::string chains;
        for (const std::string& c : limb.chains)
            chains += (chains.empty() ? "" : ", ") + c;
        auto warn = [&](const std::string& what) {
            r.diagnostics.push_back(Diagnostic::warning(
                DiagnosticCode::bad_profile, limb.mechanism + " (" + chains + "): " + what));
        };
        if (limb.mesh.triangles.empty()) {
            warn("no mesh triangle is skinned to its chains alone; it keeps its generated shape");
            continue;
        }
        const auto m =
            std::find_if(r.mechanisms.begin(), r.mechanisms.end(),
                         [&](const FittedMechanism& f) { return f.name == limb.mechanism; });
        const OutlineOutcome o = fit_outlines_of(limb.mesh, r.scaffold, *m, limb.parts, cancel);
        if (!o.profiles.empty()) {
            const std::size_t now = sheet_errors(o.scaffold);
            if (now > errors) {
                warn("outline dropped, the cutting sheets could not glue it (a glue tab would "
                     "have no room); it keeps its generated shape");
                continue;
            }
            errors = now;
        }
        r.scaffold = o.scaffold;
        r.profiles.insert(r.profiles.end(), o.profiles.begin(), o.profiles.end());
        for (const FitRepair& d : o.dropped)
            warn("outline " + d.action + ", " + d.reason);
    }
}

} // namespace popup::motion
