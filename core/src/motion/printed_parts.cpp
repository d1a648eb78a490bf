#include "popup/motion/printed_parts.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace popup {

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

/// The triangles of `posed` listed in `chosen`, with only the vertices they use, placed on the
/// card (a mirroring placement reverses each triangle so its face stays outward).
ModelMesh placed_triangles(const ModelMesh& posed, const std::vector<int>& chosen,
                           const Eigen::Matrix4d& to_card)
{
    const bool mirrors = to_card.topLeftCorner<3, 3>().determinant() < 0;
    ModelMesh out;
    out.source = posed.source;
    std::map<int, int> index; // posed vertex -> its index in `out`
    for (const int t : chosen) {
        std::array<int, 3> u{};
        for (int k = 0; k < 3; ++k) {
            const int v = posed.triangles[t][k];
            auto [it, added] = index.emplace(v, int(out.vertices.size()));
            if (added)
                out.vertices.push_back(to_card.topLeftCorner<3, 3>() * posed.vertices[v] +
                                       to_card.topRightCorner<3, 1>());
            u[k] = it->second;
        }
        if (mirrors)
            std::swap(u[1], u[2]);
        out.triangles.push_back(u);
    }
    return out;
}

/// Whether `m` hosts another mechanism (a floating layer under a rotation off the fold): the
/// one it carries takes the limb.
bool hosts_another(const MotionResult& r, const FittedMechanism& m)
{
    return std::any_of(r.mechanisms.begin(), r.mechanisms.end(), [&](const FittedMechanism& f) {
        return f.host.rfind(m.name + ".", 0) == 0;
    });
}

/// A limb without its triangles: the mechanism, its outlined parts, the chains it carries and
/// the vertices skinned to them.
PrintedPart limb_of(const MotionResult& r, const FittedMechanism& m, std::set<int>& vertices)
{
    PrintedPart limb{m.name, outlined_parts(m.kind), {}, {}};
    for (const ChainReport& chain : r.chains) {
        if (std::find(chain.mechanisms.begin(), chain.mechanisms.end(), m.name) ==
            chain.mechanisms.end())
            continue;
        for (const LinkageChain& c : r.targets.chains)
            if (c.name == chain.name)
                vertices.insert(c.vertices.begin(), c.vertices.end());
        limb.chains.push_back(chain.name);
    }
    return limb;
}

} // namespace

std::vector<PrintedPart> printed_parts(const Animation& animation, const MotionResult& r)
{
    if (animation.mesh.vertices.empty() || animation.mesh.triangles.empty())
        return {};
    const ModelMesh posed = posed_mesh(animation, double(r.targets.last_frame));
    const Eigen::Matrix4d& to_card = r.targets.animation_to_card;
    std::vector<int> owner(posed.triangles.size(), -1); // triangle -> limb, -1 the body
    std::vector<PrintedPart> limbs;
    for (const FittedMechanism& m : r.mechanisms) {
        if (outlined_parts(m.kind).empty() || hosts_another(r, m))
            continue;
        std::set<int> vertices;
        PrintedPart limb = limb_of(r, m, vertices);
        if (limb.chains.empty())
            continue;
        std::vector<int> chosen;
        for (std::size_t t = 0; t < posed.triangles.size(); ++t) {
            const std::array<int, 3>& c = posed.triangles[t];
            if (owner[t] < 0 && vertices.count(c[0]) && vertices.count(c[1]) &&
                vertices.count(c[2])) {
                owner[t] = int(limbs.size());
                chosen.push_back(int(t));
            }
        }
        if (!chosen.empty())
            limb.mesh = placed_triangles(posed, chosen, to_card);
        limbs.push_back(std::move(limb));
    }
    std::vector<int> body;
    for (std::size_t t = 0; t < owner.size(); ++t)
        if (owner[t] < 0)
            body.push_back(int(t));
    std::vector<PrintedPart> out{PrintedPart{"", {}, {}, placed_triangles(posed, body, to_card)}};
    out.insert(out.end(), std::make_move_iterator(limbs.begin()),
               std::make_move_iterator(limbs.end()));
    return out;
}

} // namespace popup
