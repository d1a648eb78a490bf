#include "choose_registrations.hpp"

#include <algorithm>

#include "fold_sides.hpp"

namespace popup::sheets {

namespace {

// Patch id → the drawn face holding its inside point, for one way of laying the piece down.
std::map<int, int> faces_of(const PieceCheck& piece, const Registration& placed)
{
    std::map<int, int> faces;
    const FlatPiece& flat = piece.local.flat;
    for (size_t i = 0; i < flat.patches.size(); ++i)
        faces[flat.patches[i]] =
            piece.drawn->face_at(placed.motion(interior_point({flat.outlines[i], flat.holes[i]})));
    return faces;
}

// One way of laying a piece on its drawing, as its glue codes and fold lines read laid so.
struct Way {
    struct Tab {
        std::map<int, FoldDirection> partners; // patches it may join → the crease they need
        FoldDirection drawn;
        std::string code;
    };
    std::vector<Tab> tabs;
    int folds_turned = 0;             // design folds whose drawn line has the other direction
    std::map<std::string, int> areas; // code → patch it lies on
};

// What the tabs, glue areas and folds of the piece say, laid down by `r`.
Way way_of(const Verification& v, const PieceCheck& piece, const Registration& r)
{
    const Scaffold& s = v.design;
    const DrawnPiece& d = *piece.drawn;
    const std::map<int, int> faces = faces_of(piece, r);
    auto patch_of = [&](int face) {
        for (const auto& [patch, f] : faces)
            if (f == face && face >= 0)
                return patch;
        return -1;
    };
    Way way;
    for (const DrawnGlue& g : d.glue)
        way.areas[g.code] = patch_of(d.face_at(interior_point({g.polygon, {}})));
    for (const DrawnFold& f : d.folds) {
        const auto [patch, tab_face] = tab_crease(d, f, patch_of);
        if (tab_face < 0)
            continue;
        // The patches the joints along this crease join its patch to.
        std::map<int, FoldDirection> partners;
        for (const Hinge& h : s.hinges)
            if (h.kind == JointKind::tab && (h.patch_a == patch || h.patch_b == patch) &&
                segment_gap({f.from, f.to}, r.motion(piece.local.flat_point(s, patch, h.from)),
                            r.motion(piece.local.flat_point(s, patch, h.to))) <=
                    v.tolerance + v.tie) {
                Hinge seen = h;
                seen.patch_a = patch;
                seen.patch_b = h.patch_a == patch ? h.patch_b : h.patch_a;
                bool unspecified = false;
                // A joint inside the partner's paper lets the tab lie on either side
                // of it, and fold either way: its crease tells nothing here.
                partners[seen.patch_b] =
                    v.joint_inside(seen.patch_b, h)
                        ? FoldDirection::unspecified
                        : drawn_direction(s, v.bends, seen, piece.local.printed_normal(s, patch),
                                          unspecified);
            }
        for (const DrawnText& t : d.texts)
            if (inside_region(d.faces[size_t(tab_face)], t.position))
                way.tabs.push_back({partners, f.direction, t.text});
    }
    // Folds: the drawn line nearest each design fold, and its direction.
    const FlatPiece& flat = piece.local.flat;
    for (size_t i = 0; i < flat.folds.size(); ++i) {
        const Hinge& h = v.hinge(flat.folds[i]);
        const std::array<Vec2, 2> line{r.motion(flat.fold_lines[i][0]),
                                       r.motion(flat.fold_lines[i][1])};
        const DrawnFold* nearest = nullptr;
        double gap = 1e300;
        for (const DrawnFold& f : d.folds)
            if (const double g = segment_gap(line, f.from, f.to); g < gap) {
                gap = g;
                nearest = &f;
            }
        bool unspecified = false;
        if (nearest && nearest->direction !=
                           drawn_direction(s, v.bends, h, piece.local.printed_normal(s, h.patch_a),
                                           unspecified))
            ++way.folds_turned;
    }
    return way;
}

// How many tabs go onto a patch the design does not join them to (or fold the wrong way onto
// it), and how many folds are drawn turned, when every piece k lies its way choice[k].
int misfits(const std::vector<std::vector<Way>>& ways, const std::vector<size_t>& choice)
{
    int count = 0;
    for (size_t k = 0; k < ways.size(); ++k) {
        if (ways[k].empty())
            continue;
        const Way& way = ways[k][choice[k]];
        count += way.folds_turned;
        for (const Way::Tab& tab : way.tabs)
            for (size_t j = 0; j < ways.size(); ++j) {
                if (ways[j].empty())
                    continue;
                const auto area = ways[j][choice[j]].areas.find(tab.code);
                if (area == ways[j][choice[j]].areas.end())
                    continue;
                const auto joint = tab.partners.find(area->second);
                count +=
                    joint == tab.partners.end() ||
                    (joint->second != FoldDirection::unspecified && joint->second != tab.drawn);
            }
    }
    return count;
}

} // namespace

// A symmetric piece fits its drawing more than one way; the glue codes tell which is meant. Of
// all combinations (a few pieces with two or four ways each), the one whose tabs go onto the
// patches the design joins them to the most often wins; ties keep each piece's best fit.
void choose_registrations(Verification& v)
{
    std::vector<std::vector<Way>> ways(v.pieces.size());
    size_t combinations = 1;
    for (size_t k = 0; k < v.pieces.size(); ++k) {
        const PieceCheck& piece = v.pieces[k];
        if (!piece.drawn)
            continue;
        for (const Registration& r : piece.candidates)
            ways[k].push_back(way_of(v, piece, r));
        combinations =
            std::min<size_t>(combinations * std::max<size_t>(ways[k].size(), 1), size_t(1) << 20);
    }
    std::vector<size_t> choice(v.pieces.size(), 0), best = choice;
    int fewest = misfits(ways, choice);
    if (combinations <= 4096) {
        for (size_t n = 1; n < combinations && fewest > 0; ++n) {
            size_t rest = n;
            for (size_t k = 0; k < ways.size(); ++k) {
                const size_t count = std::max<size_t>(ways[k].size(), 1);
                choice[k] = rest % count;
                rest /= count;
            }
            if (const int m = misfits(ways, choice); m < fewest) {
                fewest = m;
                best = choice;
            }
        }
    } else { // one piece at a time, in assembly order, until no piece turned round helps
        for (bool better = true; better && fewest > 0;) {
            better = false;
            for (size_t k = 0; k < ways.size(); ++k)
                for (size_t w = 0; w < ways[k].size(); ++w) {
                    choice = best;
                    choice[k] = w;
                    if (const int m = misfits(ways, choice); m < fewest) {
                        fewest = m;
                        best = choice;
                        better = true;
                    }
                }
        }
    }
    for (size_t k = 0; k < v.pieces.size(); ++k)
        if (v.pieces[k].drawn)
            v.pieces[k].placed = v.pieces[k].candidates[best[k]];
}

} // namespace popup::sheets
