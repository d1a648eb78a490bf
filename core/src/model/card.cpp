#include "popup/model/card.hpp"

#include <cmath>

namespace popup {

Result<Scaffold> make_card(const CardParams& p)
{
    Result<Scaffold> r;
    if (!(p.width > 0 && p.width <= 2000))
        range_error(r.diagnostics, p.name, "Width", p.width, "mm", "> 0 and <= 2000 mm");
    if (!(p.depth > 0 && p.depth <= 2000))
        range_error(r.diagnostics, p.name, "Depth", p.depth, "mm", "> 0 and <= 2000 mm");
    if (!(p.paper_thickness >= 0 && p.paper_thickness <= 5))
        range_error(r.diagnostics, p.name, "PaperThickness", p.paper_thickness, "mm",
                    ">= 0 and <= 5 mm");
    if (!r.diagnostics.empty()) {
        r.ok = false;
        return r;
    }
    Scaffold& s = r.value;
    s.name = "card";
    s.paper_thickness = p.paper_thickness;
    Patch ground;
    ground.id = 0;
    ground.name = "Card.ground";
    ground.role = PatchRole::ground;
    ground.outer = {{0, 0, 0}, {p.depth, 0, 0}, {p.depth, p.width, 0}, {0, p.width, 0}};
    Patch backdrop;
    backdrop.id = 1;
    backdrop.name = "Card.backdrop";
    backdrop.role = PatchRole::backdrop;
    backdrop.outer = {{-p.depth, 0, 0}, {0, 0, 0}, {0, p.width, 0}, {-p.depth, p.width, 0}};
    s.patches = {ground, backdrop};
    for (Patch& patch : s.patches)
        patch.derive_frame();
    s.ground = 0;
    s.backdrop = 1;
    s.hinges.push_back({0, 0, 1, {0, 0, 0}, {0, p.width, 0}, FoldDirection::valley});
    return r;
}

BasePatchPair central_fold(const Scaffold& card)
{
    BasePatchPair pair;
    pair.name = "central fold";
    pair.ground = card.ground;
    pair.backdrop = card.backdrop;
    const Patch* ground = card.find_patch(card.ground);
    const Patch* backdrop = card.find_patch(card.backdrop);
    Eigen::AlignedBox3d g, b;
    for (const Vec3& x : ground->outer)
        g.extend(x);
    for (const Vec3& x : backdrop->outer)
        b.extend(x);
    pair.length = g.max().y() - g.min().y();
    pair.origin = Vec3(0, g.min().y(), 0);
    pair.ground_depth = g.max().x();
    pair.backdrop_depth = -b.min().x();
    return pair;
}

} // namespace popup
