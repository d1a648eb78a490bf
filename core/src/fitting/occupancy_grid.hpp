#pragma once
// Internal: the volume a model's surface encloses, on a voxel grid, so that an assembly of
// touching solids, a hollow shell with window holes and a soup of open sheets all act as the one
// object a person sees (docs/MATH.md, "The model's volume").
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "popup/input/model_mesh.hpp"

namespace popup {

class OccupancyGrid {
public:
    /// The model's triangles voxelised on a grid of `cells` along its longest side, closed by
    /// `close_cells` (gaps up to twice as wide are bridged: windows, cracks, seams between
    /// parts) and filled: every cell no path from outside reaches is solid.
    OccupancyGrid(const ModelMesh& model, int cells, int close_cells);

    /// True when `p` (model units) lies in a solid cell; false outside the grid.
    bool solid_at(const Vec3& p) const;
    double cell() const { return cell_; }
    /// Solid cells over all cells of the grid (a measure of how much the closing filled).
    double solid_share() const;

private:
    std::int64_t index(int x, int y, int z) const
    {
        return (std::int64_t(z) * dims_.y() + y) * dims_.x() + x;
    }
    void mark_surface(const ModelMesh& model);
    void dilate(std::vector<std::uint8_t>& mask, int radius) const;
    std::vector<std::uint8_t> outside_of(const std::vector<std::uint8_t>& walls) const;

    Vec3 origin_ = Vec3::Zero();
    double cell_ = 1.0;
    Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
    std::vector<std::uint8_t> solid_;
};

} // namespace popup
