#include "assembly_order.hpp"

#include <deque>
#include <map>
#include <set>

namespace popup::sheets {

std::vector<int> assembly_order(const Scaffold& s, const std::vector<std::vector<int>>& pieces,
                                Diagnostics& diagnostics)
{
    std::map<int, int> piece_of;
    for (size_t k = 0; k < pieces.size(); ++k)
        for (int id : pieces[k])
            piece_of[id] = int(k);
    std::vector<std::set<int>> neighbours(pieces.size());
    auto join = [&](int a, int b) {
        const int pa = piece_of.at(a), pb = piece_of.at(b);
        if (pa != pb) {
            neighbours[pa].insert(pb);
            neighbours[pb].insert(pa);
        }
    };
    for (const Hinge& h : s.hinges)
        join(h.patch_a, h.patch_b);
    for (const Glue& g : s.glue)
        join(g.patch_a, g.patch_b);

    std::vector<int> depth(pieces.size(), -1); // joints between each piece and the card
    std::vector<int> order;
    const int card = piece_of.at(s.ground);
    depth[card] = 0;
    std::deque<int> queue{card};
    while (!queue.empty()) {
        const int k = queue.front();
        queue.pop_front();
        order.push_back(k);
        for (int n : neighbours[k])
            if (depth[n] < 0) {
                depth[n] = depth[k] + 1;
                queue.push_back(n);
            }
    }
    for (size_t k = 0; k < pieces.size(); ++k)
        if (depth[k] < 0) {
            diagnostics.push_back(
                Diagnostic::error(DiagnosticCode::detached_piece,
                                  "the piece holding patch " + std::to_string(pieces[k].front()) +
                                      " is not joined to the card by any tab or glue",
                                  about_patches(pieces[k])));
            depth[k] = int(pieces.size());
            order.push_back(int(k));
        }
    return order;
}

} // namespace popup::sheets
