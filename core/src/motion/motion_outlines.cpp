#include "motion_outlines.hpp"

#include <algorithm>

#include "popup/fitting/fit_outlines.hpp"

namespace popup::motion {

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
    for (const PrintedPart& limb : printed_parts(animation, r)) {
        if (limb.mechanism.empty())
            continue; // the body: printed on the pages, outlined by nothing
        std::string chains;
        for (const std::string& c : limb.chains)
            chains += (chains.empty() ? "" : ", ") + c;
        if (limb.mesh.triangles.empty()) {
            r.diagnostics.push_back(Diagnostic::warning(
                DiagnosticCode::bad_profile,
                limb.mechanism + " (" + chains +
                    "): no mesh triangle is skinned to its chains alone; it keeps its generated "
                    "shape"));
            continue;
        }
        const auto m =
            std::find_if(r.mechanisms.begin(), r.mechanisms.end(),
                         [&](const FittedMechanism& f) { return f.name == limb.mechanism; });
        const OutlineOutcome o = fit_outlines_of(limb.mesh, r.scaffold, *m, limb.parts, cancel);
        r.scaffold = o.scaffold;
        r.profiles.insert(r.profiles.end(), o.profiles.begin(), o.profiles.end());
        for (const FitRepair& d : o.dropped)
            r.diagnostics.push_back(Diagnostic::warning(
                DiagnosticCode::bad_profile,
                limb.mechanism + " (" + chains + "): outline " + d.action + ", " + d.reason));
    }
}

} // namespace popup::motion
