#include "occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

namespace popup {

OccupancyGrid::OccupancyGrid(const ModelMesh& model, int cells, int close_cells)
{
    Eigen::AlignedBox3d box;
    for (const Vec3& v : model.vertices)
        box.extend(v);
    if (box.isEmpty())
        return;
    cell_ = std::max(box.sizes().maxCoeff() / std::max(cells, 1), 1e-300);
    // Room for the closing's dilation and one free cell all round, so the outside is connected.
    const int pad = close_cells + 2;
    origin_ = box.min() - Vec3::Constant(pad * cell_);
    for (int k = 0; k < 3; ++k)
        dims_[k] = int(std::ceil(box.sizes()[k] / cell_)) + 2 * pad + 1;
    solid_.assign(size_t(dims_.prod()), 0);
    mark_surface(model);
    std::vector<std::uint8_t> walls = solid_;
    dilate(walls, close_cells);
    std::vector<std::uint8_t> outside = outside_of(walls);
    // Closing: the outside grows back by the radius the walls grew, so the filled volume ends
    // at the model's surface again, with the gaps narrower than the walls' growth bridged.
    dilate(outside, close_cells);
    for (size_t i = 0; i < solid_.size(); ++i)
        solid_[i] = !outside[i];
}

bool OccupancyGrid::solid_at(const Vec3& p) const
{
    if (solid_.empty())
        return false;
    const Vec3 g = (p - origin_) / cell_;
    const int x = int(std::floor(g.x())), y = int(std::floor(g.y())), z = int(std::floor(g.z()));
    if (x < 0 || y < 0 || z < 0 || x >= dims_.x() || y >= dims_.y() || z >= dims_.z())
        return false;
    return solid_[size_t(index(x, y, z))] != 0;
}

double OccupancyGrid::solid_share() const
{
    if (solid_.empty())
        return 0.0;
    return double(std::count(solid_.begin(), solid_.end(), 1)) / double(solid_.size());
}

void OccupancyGrid::mark_surface(const ModelMesh& model)
{
    auto mark = [&](const Vec3& g) {
        const int x = std::clamp(int(std::floor(g.x())), 0, dims_.x() - 1);
        const int y = std::clamp(int(std::floor(g.y())), 0, dims_.y() - 1);
        const int z = std::clamp(int(std::floor(g.z())), 0, dims_.z() - 1);
        solid_[size_t(index(x, y, z))] = 1;
    };
    for (const auto& t : model.triangles) {
        const Vec3 a = (model.vertices[t[0]] - origin_) / cell_;
        const Vec3 ab = (model.vertices[t[1]] - origin_) / cell_ - a;
        const Vec3 ac = (model.vertices[t[2]] - origin_) / cell_ - a;
        // Points half a cell apart along both edges cover every cell the triangle crosses.
        const double longest = std::max({ab.norm(), ac.norm(), (ac - ab).norm()});
        const int n = std::max(1, int(std::ceil(2.0 * longest)));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j)
                mark(a + (double(i) / n) * ab + (double(j) / n) * ac);
    }
}

void OccupancyGrid::dilate(std::vector<std::uint8_t>& mask, int radius) const
{
    if (radius <= 0)
        return;
    // Separable: a cube of side 2·radius + 1 is three passes of a line of that length.
    const Eigen::Vector3i step(1, dims_.x(), dims_.x() * dims_.y());
    std::vector<std::uint8_t> line;
    for (int axis = 0; axis < 3; ++axis) {
        const int length = dims_[axis];
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        line.resize(size_t(length));
        for (int u = 0; u < dims_[a1]; ++u)
            for (int v = 0; v < dims_[a2]; ++v) {
                const std::int64_t start = std::int64_t(u) * step[a1] + std::int64_t(v) * step[a2];
                int last = -1 - radius; // the last set cell seen, looking ahead by `radius`
                for (int i = 0; i < length; ++i)
                    line[size_t(i)] = mask[size_t(start + std::int64_t(i) * step[axis])];
                for (int i = 0; i < length + radius; ++i) {
                    if (i < length && line[size_t(i)])
                        last = i;
                    const int out = i - radius;
                    if (out >= 0)
                        mask[size_t(start + std::int64_t(out) * step[axis])] =
                            last >= out - radius ? 1 : 0;
                }
            }
    }
}

std::vector<std::uint8_t> OccupancyGrid::outside_of(const std::vector<std::uint8_t>& walls) const
{
    std::vector<std::uint8_t> outside(walls.size(), 0);
    std::vector<std::int64_t> stack{0}; // a corner: the padding keeps it outside every wall
    outside[0] = 1;
    // Steps by index only: one from a row's end lands on the next row's start, both in the
    // padding the walls never reach (two cells or more), which the corner reaches anyway.
    const std::int64_t size = std::int64_t(walls.size());
    const std::int64_t sx = 1, sy = dims_.x(), sz = std::int64_t(dims_.x()) * dims_.y();
    while (!stack.empty()) {
        const std::int64_t i = stack.back();
        stack.pop_back();
        for (const std::int64_t j : {i - sx, i + sx, i - sy, i + sy, i - sz, i + sz})
            if (j >= 0 && j < size && !outside[size_t(j)] && !walls[size_t(j)]) {
                outside[size_t(j)] = 1;
                stack.push_back(j);
            }
    }
    return outside;
}

} // namespace popup
