#include "popup/sheets/pieces.hpp"

#include <map>
#include <numeric>

namespace popup {

std::vector<std::vector<int>> cut_pieces(const Scaffold& s)
{
    const int n = int(s.patches.size());
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    for (const Hinge& h : s.hinges) {
        const int a = s.patch_index(h.patch_a), b = s.patch_index(h.patch_b);
        if (h.kind == JointKind::fold && a >= 0 && b >= 0)
            parent[find(a)] = find(b);
    }
    std::map<int, int> piece_of_root;
    std::vector<std::vector<int>> pieces;
    for (int i = 0; i < n; ++i) {
        auto [it, fresh] = piece_of_root.try_emplace(find(i), int(pieces.size()));
        if (fresh)
            pieces.emplace_back();
        pieces[it->second].push_back(s.patches[i].id);
    }
    return pieces;
}

} // namespace popup
