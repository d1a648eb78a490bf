#include "body_graph.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace popup {

namespace {
struct DisjointSets {
    std::vector<int> parent;
    explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int i) { return parent[i] == i ? i : parent[i] = find(parent[i]); }
    void join(int a, int b) { parent[find(a)] = find(b); }
};
/// Every free group must hang from the base through a hinge or a slit, and the two bases must
/// share the central fold: otherwise nothing holds the patches and the solver has no equations.
void check_attachment(const Scaffold& s, const BodyGraph& g, Result<BodyGraph>& r)
{
    const bool bases_hinged = std::any_of(s.hinges.begin(), s.hinges.end(), [&](const Hinge& h) {
        const int a = g.body_of_patch[s.patch_index(h.patch_a)];
        const int b = g.body_of_patch[s.patch_index(h.patch_b)];
        return a != b && g.is_base(a) && g.is_base(b);
    });
    if (!bases_hinged)
        r.fail(DiagnosticCode::bases_not_hinged,
               "no hinge joins the ground and the backdrop: the card needs its central fold",
               about_patches({s.ground, s.backdrop}));
    for (size_t c = 0; c < g.components.size(); ++c) {
        const auto touches_base = [&](int body_a, int body_b) {
            return g.is_base(body_a) || g.is_base(body_b);
        };
        bool held = false;
        for (int j : g.component_joints[c])
            held = held || touches_base(g.joints[j].body_a, g.joints[j].body_b);
        for (int k : g.component_slits[c])
            held = held || touches_base(g.slits[k].body_cut, g.slits[k].body_through);
        if (held)
            continue;
        std::vector<int> ids;
        std::ostringstream names;
        for (size_t i = 0; i < s.patches.size(); ++i)
            if (g.component_of_body[g.body_of_patch[i]] == int(c)) {
                names << (ids.empty() ? "" : ", ") << "patch " << s.patches[i].id;
                ids.push_back(s.patches[i].id);
            }
        r.fail(DiagnosticCode::detached_patch,
               names.str() + (ids.size() == 1 ? " is" : " are") +
                   " joined to the card by no hinge or slit: hinge or glue " +
                   (ids.size() == 1 ? "it" : "them") + " to a patch of the card",
               about_patches(ids));
    }
}

} // namespace

Result<BodyGraph> build_body_graph(const Scaffold& s)
{
    Result<BodyGraph> r;
    BodyGraph& g = r.value;
    const int n = int(s.patches.size());
    DisjointSets glued(n);
    for (const Glue& glue : s.glue)
        glued.join(s.patch_index(glue.patch_a), s.patch_index(glue.patch_b));

    std::vector<int> body_of_root(n, -1);
    g.body_of_patch.resize(n);
    for (int i = 0; i < n; ++i) {
        int& body = body_of_root[glued.find(i)];
        if (body < 0)
            body = g.body_count++;
        g.body_of_patch[i] = body;
    }
    g.ground = g.body_of_patch[s.patch_index(s.ground)];
    g.backdrop = g.body_of_patch[s.patch_index(s.backdrop)];
    if (g.ground == g.backdrop) {
        r.fail(DiagnosticCode::base_glued,
               "the ground and the backdrop are glued into one rigid body",
               about_patches({s.ground, s.backdrop}));
        return r;
    }

    g.center.assign(g.body_count, Vec3::Zero());
    std::vector<int> count(g.body_count, 0);
    for (int i = 0; i < n; ++i)
        for (const Vec3& x : s.patches[i].outer) {
            g.center[g.body_of_patch[i]] += x;
            ++count[g.body_of_patch[i]];
        }
    for (int b = 0; b < g.body_count; ++b)
        g.center[b] /= double(std::max(count[b], 1));

    DisjointSets linked(g.body_count);
    for (size_t h = 0; h < s.hinges.size(); ++h) {
        const Hinge& hinge = s.hinges[h];
        const int a = g.body_of_patch[s.patch_index(hinge.patch_a)];
        const int b = g.body_of_patch[s.patch_index(hinge.patch_b)];
        // A hinge inside one body is rigid; the central fold between the bases is driven.
        if (a == b || (g.is_base(a) && g.is_base(b)))
            continue;
        g.joints.push_back({int(h), a, b, {hinge.from, hinge.to}});
        if (!g.is_base(a) && !g.is_base(b))
            linked.join(a, b);
    }

    for (size_t k = 0; k < s.slits.size(); ++k) {
        const Slit& sl = s.slits[k];
        const int cut = g.body_of_patch[s.patch_index(sl.patch_cut)];
        const int through = g.body_of_patch[s.patch_index(sl.patch_through)];
        if (cut == through || (g.is_base(cut) && g.is_base(through)))
            continue;
        const Patch& p = *s.find_patch(sl.patch_through);
        g.slits.push_back({int(k), cut, through, {sl.from, sl.to}, p.origin, p.normal});
        if (!g.is_base(cut) && !g.is_base(through))
            linked.join(cut, through);
    }

    g.component_of_body.assign(g.body_count, -1);
    std::vector<int> component_of_root(g.body_count, -1);
    for (int b = 0; b < g.body_count; ++b) {
        if (g.is_base(b))
            continue;
        int& c = component_of_root[linked.find(b)];
        if (c < 0) {
            c = int(g.components.size());
            g.components.emplace_back();
        }
        g.components[c].push_back(b);
        g.component_of_body[b] = c;
    }
    g.component_slits.resize(g.components.size());
    for (size_t k = 0; k < g.slits.size(); ++k) {
        const SlitJoint& sl = g.slits[k];
        const int c = g.is_base(sl.body_cut) ? g.component_of_body[sl.body_through]
                                             : g.component_of_body[sl.body_cut];
        g.component_slits[c].push_back(int(k));
    }
    g.component_joints.resize(g.components.size());
    for (size_t j = 0; j < g.joints.size(); ++j) {
        const Joint& joint = g.joints[j];
        const int c = g.is_base(joint.body_a) ? g.component_of_body[joint.body_b]
                                              : g.component_of_body[joint.body_a];
        g.component_joints[c].push_back(int(j));
    }
    check_attachment(s, g, r);
    return r;
}

} // namespace popup
