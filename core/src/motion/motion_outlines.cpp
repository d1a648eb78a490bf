#include "motion_outlines.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "popup/fitting/fit_outlines.hpp"

namespace popup::motion {

std::vector<std::string> outlined_parts(MechanismKind kind)
{
    switch (kind) {
    case MechanismKind::rotation_arm:
        return {"wing_arm"};
    case MechanismKind::vertical_translation:
    case MechanismKind::floating_layer:
        return {"TG", "TB"};
    case MechanismKind::horizontal_translation:
        return {"M"};
    case MechanismKind::step_fold:
        return {"tread"};
    default:
        return {};
    }
}

namespace {

/// The triangles of `posed` whose three corners are among `vertices`, placed on the card.
ModelMesh body_part(const ModelMesh& posed, const std::set<int>& vertices,
                    const Eigen::Matrix4d& to_card)
{
    ModelMesh out;
    out.source = posed.source;
    std::map<int, int> index; // posed vertex -> its index in `out`
    for (const std::array<int, 3>& t : posed.triangles) {
        if (!vertices.count(t[0]) || !vertices.count(t[1]) || !vertices.count(t[2]))
            continue;
        std::array<int, 3> u{};
        for (int k = 0; k < 3; ++k) {
            auto [it, added] = index.emplace(t[k], int(out.vertices.size()));
            if (added)
                out.vertices.push_back(to_card.topLeftCorner<3, 3>() * posed.vertices[t[k]] +
                                       to_card.topRightCorner<3, 1>());
            u[k] = it->second;
        }
        out.triangles.push_back(u);
    }
    return out;
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
    const ModelMesh posed = posed_mesh(animation, double(r.targets.last_frame));
    // The chains each mechanism carries (a merged patch carries all of its chains' parts).
    for (const FittedMechanism& m : r.mechanisms) {
        const std::vector<std::string> parts = outlined_parts(m.kind);
        if (parts.empty())
            continue;
        // A mechanism that hosts another (the floating layer under a rotation off the fold)
        // stands under the part; the one it carries takes the outline.
        const bool hosts =
            std::any_of(r.mechanisms.begin(), r.mechanisms.end(), [&](const FittedMechanism& f) {
                return f.host.rfind(m.name + ".", 0) == 0;
            });
        if (hosts)
            continue;
        std::set<int> vertices;
        std::string chains;
        for (std::size_t j = 0; j < r.chains.size(); ++j) {
            const std::vector<std::string>& carried = r.chains[j].mechanisms;
            if (std::find(carried.begin(), carried.end(), m.name) == carried.end())
                continue;
            for (const LinkageChain& c : r.targets.chains)
                if (c.name == r.chains[j].name)
                    vertices.insert(c.vertices.begin(), c.vertices.end());
            chains += (chains.empty() ? "" : ", ") + r.chains[j].name;
        }
        const ModelMesh part = body_part(posed, vertices, r.targets.animation_to_card);
        if (part.triangles.empty()) {
            r.diagnostics.push_back(Diagnostic::warning(
                DiagnosticCode::bad_profile, m.name + " (" + chains +
                                                 "): no mesh triangle is skinned to its chains "
                                                 "alone; it keeps its generated shape"));
            continue;
        }
        const OutlineOutcome o = fit_outlines_of(part, r.scaffold, m, parts, cancel);
        r.scaffold = o.scaffold;
        r.profiles.insert(r.profiles.end(), o.profiles.begin(), o.profiles.end());
        for (const FitRepair& d : o.dropped)
            r.diagnostics.push_back(Diagnostic::warning(DiagnosticCode::bad_profile,
                                                        m.name + " (" + chains + "): outline " +
                                                            d.action + ", " + d.reason));
    }
}

} // namespace popup::motion
