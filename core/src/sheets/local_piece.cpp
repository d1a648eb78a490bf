#include "local_piece.hpp"

#include <algorithm>

namespace popup::sheets {

Vec2 LocalPiece::flat_point(const Scaffold& s, int patch, const Vec3& x) const
{
    const Patch& root = *s.find_patch(flat.patches.front());
    const Vec2 p = root.to_local(flat.unfold[index_of.at(patch)].apply(x));
    return printed_back ? Vec2(p.x(), -p.y()) : p;
}

Vec3 LocalPiece::printed_normal(const Scaffold& s, int patch) const
{
    const Patch& root = *s.find_patch(flat.patches.front());
    const Vec3 up = flat.unfold[index_of.at(patch)].rotation.transpose() * root.normal;
    return printed_back ? Vec3(-up) : up;
}

Vec2 left_normal(const Vec2& direction)
{
    return {-direction.y(), direction.x()};
}

namespace {

void snap(std::vector<Vec2>& seen, Vec2& p, double tol)
{
    for (const Vec2& q : seen)
        if ((q - p).norm() <= tol) {
            p = q;
            return;
        }
    seen.push_back(p);
}

} // namespace

Result<LocalPiece> lay_flat(const Scaffold& s, const std::vector<int>& patches, double tol,
                            bool printed_back)
{
    Result<LocalPiece> r;
    Result<FlatPiece> flat = unfold_piece(s, patches);
    if (!flat.ok) {
        r.fail_with(flat.diagnostics);
        return r;
    }
    LocalPiece& piece = r.value;
    piece.flat = std::move(flat.value);
    for (size_t k = 0; k < piece.flat.patches.size(); ++k)
        piece.index_of[piece.flat.patches[k]] = int(k);
    if (printed_back) { // turned over about the root frame's first axis
        piece.printed_back = true;
        auto turn = [](Vec2& p) { p.y() = -p.y(); };
        for (Loop2& loop : piece.flat.outlines)
            std::for_each(loop.begin(), loop.end(), turn);
        for (auto& holes : piece.flat.holes)
            for (Loop2& loop : holes)
                std::for_each(loop.begin(), loop.end(), turn);
        for (auto& line : piece.flat.fold_lines)
            std::for_each(line.begin(), line.end(), turn);
    }
    std::vector<Vec2> seen;
    for (Loop2& loop : piece.flat.outlines)
        for (Vec2& p : loop)
            snap(seen, p, tol);
    for (auto& holes : piece.flat.holes)
        for (Loop2& loop : holes)
            for (Vec2& p : loop)
                snap(seen, p, tol);
    for (auto& line : piece.flat.fold_lines)
        for (Vec2& p : line)
            snap(seen, p, tol);
    return r;
}

} // namespace popup::sheets
