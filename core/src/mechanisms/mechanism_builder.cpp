#include "mechanism_builder.hpp"

#include <algorithm>

namespace popup {

MechanismBuilder::MechanismBuilder(Scaffold& scaffold, const BasePatchPair& host, std::string name)
    : scaffold_(scaffold), host_(host)
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

void MechanismBuilder::glue(int a, int b)
{
    scaffold_.glue.push_back({a, b});
}

} // namespace popup
