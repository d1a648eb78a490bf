#include "popup/sheets/unfold_piece.hpp"

#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <sstream>

#include "../geometry/turn_about.hpp"

namespace popup {

namespace {

// Unit direction from the fold line (through a along d) toward x, in the plane across the fold.
Vec3 across(const Vec3& x, const Vec3& a, const Vec3& d)
{
    Vec3 v = x - a;
    v -= v.dot(d) * d;
    return v.normalized();
}

} // namespace

Result<FlatPiece> unfold_piece(const Scaffold& input, const std::vector<int>& piece)
{
    Result<FlatPiece> r;
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    const Scaffold& s = checked.value;
    if (piece.empty()) {
        r.fail(DiagnosticCode::empty_piece, "a piece needs at least one patch");
        return r;
    }
    const std::set<int> members(piece.begin(), piece.end());
    for (int id : piece)
        if (!s.find_patch(id)) {
            r.fail(DiagnosticCode::unknown_patch,
                   "patch " + std::to_string(id) + " of the piece is not in the scaffold");
            return r;
        }
    std::vector<const Hinge*> folds;
    for (const Hinge& h : s.hinges)
        if (h.kind == JointKind::fold && members.count(h.patch_a) && members.count(h.patch_b))
            folds.push_back(&h);

    // Breadth-first from the root: each patch turns about its fold with an unfolded parent.
    FlatPiece& flat = r.value;
    std::map<int, Pose> unfold{{piece.front(), Pose{}}};
    std::deque<int> queue{piece.front()};
    std::set<const Hinge*> tree;
    flat.patches.push_back(piece.front());
    while (!queue.empty()) {
        const int parent = queue.front();
        queue.pop_front();
        const Pose& up = unfold.at(parent);
        for (const Hinge* h : folds) {
            if (h->patch_a != parent && h->patch_b != parent)
                continue;
            const int child = h->patch_a == parent ? h->patch_b : h->patch_a;
            if (unfold.count(child))
                continue;
            const Vec3 a = up.apply(h->from);
            const Vec3 d = (up.apply(h->to) - a).normalized();
            const Vec3 into_parent = across(up.apply(s.find_patch(parent)->centroid()), a, d);
            const Vec3 into_child = across(up.apply(s.find_patch(child)->centroid()), a, d);
            // Open flat: the child ends on the far side of the fold from its parent.
            const Vec3 target = -into_parent;
            const double angle =
                std::atan2(d.dot(into_child.cross(target)), into_child.dot(target));
            unfold[child] = up.then(turn_about(a, d, angle));
            tree.insert(h);
            flat.patches.push_back(child);
            queue.push_back(child);
        }
    }
    if (flat.patches.size() != members.size()) {
        for (int id : piece)
            if (!unfold.count(id)) {
                r.fail(DiagnosticCode::disconnected_piece,
                       patch_subject(*s.find_patch(id)) + " is not joined to " +
                           patch_subject(*s.find_patch(piece.front())) + " by folds of the piece",
                       about_patches({id, piece.front()}));
                break;
            }
        return r;
    }
    // A fold outside the tree closes a loop: both patches must put it in the same place.
    const double tol = 1e-6 * std::max(s.size(), 1.0);
    for (const Hinge* h : folds) {
        if (tree.count(h))
            continue;
        const Pose& pa = unfold.at(h->patch_a);
        const Pose& pb = unfold.at(h->patch_b);
        const double gap = std::max((pa.apply(h->from) - pb.apply(h->from)).norm(),
                                    (pa.apply(h->to) - pb.apply(h->to)).norm());
        if (gap > tol) {
            std::ostringstream m;
            m << "hinge " << h->id << " closes a loop of folds that does not lie flat: its two "
              << "sides land " << gap
              << " mm apart (make one hinge of the loop a tab joint: \"joint\": \"tab\")";
            r.fail(DiagnosticCode::not_developable, m.str(),
                   about_patches({h->patch_a, h->patch_b}));
        }
    }
    const Patch& root = *s.find_patch(piece.front());
    for (const auto& [id, u] : unfold)
        for (const Vec3& x : s.find_patch(id)->outer)
            if (std::abs((u.apply(x) - root.origin).dot(root.normal)) > tol) {
                r.fail(DiagnosticCode::not_flat,
                       patch_subject(*s.find_patch(id)) + " does not come to lie flat",
                       about_patches({id}));
                break;
            }
    if (!r.ok)
        return r;

    for (int id : flat.patches) {
        const Patch& p = *s.find_patch(id);
        const Pose& u = unfold.at(id);
        flat.unfold.push_back(u);
        Loop2 outline;
        for (const Vec3& x : p.outer)
            outline.push_back(root.to_local(u.apply(x)));
        flat.outlines.push_back(outline);
        std::vector<Loop2> holes;
        for (const Loop3& hole : p.holes) {
            Loop2 loop;
            for (const Vec3& x : hole)
                loop.push_back(root.to_local(u.apply(x)));
            holes.push_back(loop);
        }
        flat.holes.push_back(holes);
    }
    for (const Hinge* h : folds) {
        const Pose& u = unfold.at(h->patch_a);
        flat.folds.push_back(h->id);
        flat.fold_lines.push_back({root.to_local(u.apply(h->from)), root.to_local(u.apply(h->to))});
    }
    return r;
}

} // namespace popup
