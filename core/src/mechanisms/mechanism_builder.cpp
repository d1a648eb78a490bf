#include "mechanism_builder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace popup {

MechanismBuilder::MechanismBuilder(Scaffold& scaffold, const BasePatchPair& host, std::string name)
    : scaffold_(scaffold), host_(host), first_patch_(scaffold.patches.size()),
      first_hinge_(scaffold.hinges.size()), first_glue_(scaffold.glue.size())
{
    parts_.name = std::move(name);
    parts_.host = host.name;
}

int MechanismBuilder::patch(const std::vector<Vec3>& local, PatchRole role, const std::string& part)
{
    Patch p;
    p.id = 0;
    for (const Patch& other : scaffold_.patches)
        p.id = std::max(p.id, other.id + 1);
    p.name = parts_.name + "." + part;
    p.role = role;
    for (const Vec3& x : local)
        p.outer.push_back(world(x));
    p.derive_frame();
    scaffold_.patches.push_back(p);
    parts_.patches.push_back(p.id);
    return p.id;
}

void MechanismBuilder::hinge(int a, int b, const Vec3& local_from, const Vec3& local_to,
                             FoldDirection direction)
{
    int id = 0;
    for (const Hinge& h : scaffold_.hinges)
        id = std::max(id, h.id + 1);
    scaffold_.hinges.push_back({id, a, b, world(local_from), world(local_to), direction});
}

void MechanismBuilder::tab(int a, int b, const Vec3& local_from, const Vec3& local_to,
                           FoldDirection direction)
{
    hinge(a, b, local_from, local_to, direction);
    scaffold_.hinges.back().kind = JointKind::tab;
}

void MechanismBuilder::glue(int a, int b)
{
    scaffold_.glue.push_back({a, b});
}

Result<MechanismParts> MechanismBuilder::finish()
{
    Result<MechanismParts> r;
    const double tol = 1e-6 * std::max(scaffold_.size(), 1.0);
    // The host pair must be this scaffold's: its patches here, its hinge on both of them.
    for (int id : {host_.ground, host_.backdrop}) {
        const Patch* p = scaffold_.find_patch(id);
        const Vec3 end = host_.origin + host_.length * host_.axis;
        if (p && p->contains(host_.origin, 10 * tol) && p->contains(end, 10 * tol))
            continue;
        r.fail(DiagnosticCode::bad_host,
               parts_.name + ": host " + host_.name + " is not a base patch pair of this design" +
                   (p ? ": its hinge is not on patch " : ": it names patch ") + std::to_string(id) +
                   (p ? "" : ", which this design does not have"),
               about_parameter("Host"));
        break;
    }
    // Parameters inside their ranges can still make a part vanish or run off to infinity (a
    // 1e300 mm slope, a wall angle a hair below 90°): the mechanism is in error, not the card.
    auto degenerate = [&](const std::string& what) {
        r.fail(DiagnosticCode::bad_parameter, parts_.name + ": these parameters make " + what +
                                                  "; move them away from the ends of their ranges");
    };
    for (size_t k = first_patch_; k < scaffold_.patches.size() && r.ok; ++k) {
        Patch& p = scaffold_.patches[k];
        const bool finite = std::all_of(p.outer.begin(), p.outer.end(), [](const Vec3& x) {
            return x.allFinite() && x.cwiseAbs().maxCoeff() <= 1e6;
        });
        if (!finite || !std::isfinite(p.derive_frame()) || !(p.area() > tol * tol))
            degenerate(p.name + " degenerate (no area, or coordinates beyond ±1e6 mm)");
    }
    for (size_t k = first_hinge_; k < scaffold_.hinges.size() && r.ok; ++k) {
        const Hinge& h = scaffold_.hinges[k];
        if (!h.from.allFinite() || !h.to.allFinite() ||
            !((h.to - h.from).norm() > shortest_fold(scaffold_)))
            degenerate("fold " + std::to_string(h.id) + " shorter than " +
                       std::to_string(shortest_fold(scaffold_)) + " mm");
    }
    for (size_t k = first_hinge_; k < scaffold_.hinges.size() && r.ok; ++k) {
        const Hinge& h = scaffold_.hinges[k];
        for (int id : {h.patch_a, h.patch_b}) {
            const Patch* p = scaffold_.find_patch(id);
            if (p->contains(h.from, 10 * tol) && p->contains(h.to, 10 * tol))
                continue;
            std::ostringstream m;
            m << parts_.name << ": does not fit on " << host_.name << ": one of its folds runs off "
              << (p->name.empty() ? "patch " + std::to_string(p->id) : p->name)
              << "; make it smaller or move it";
            r.fail(DiagnosticCode::mechanism_does_not_fit, m.str(), {{id}, "Host", std::nullopt});
            break;
        }
    }
    if (!r.ok) {
        scaffold_.patches.resize(first_patch_);
        scaffold_.hinges.resize(first_hinge_);
        scaffold_.glue.resize(first_glue_);
        return r;
    }
    r.value = parts_;
    return r;
}

} // namespace popup
