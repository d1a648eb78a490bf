#pragma once
// Shared by the binding files: point lists as numpy arrays (one row per point) and back.
#include <vector>

#include <Eigen/Core>

#include "popup/model/patch.hpp"

namespace popup::bindings {

using Rows3d = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Rows2d = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

inline Rows3d rows_of(const std::vector<Vec3>& points)
{
    Rows3d m(points.size(), 3);
    for (size_t i = 0; i < points.size(); ++i)
        m.row(i) = points[i].transpose();
    return m;
}

inline Rows2d rows_of(const Loop2& loop)
{
    Rows2d m(loop.size(), 2);
    for (size_t i = 0; i < loop.size(); ++i)
        m.row(i) = loop[i].transpose();
    return m;
}

inline std::vector<Vec3> points_of(const Rows3d& m)
{
    std::vector<Vec3> points(m.rows());
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        points[i] = m.row(i).transpose();
    return points;
}

inline Loop2 loop_of(const Rows2d& m)
{
    Loop2 loop(m.rows());
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        loop[i] = m.row(i).transpose();
    return loop;
}

} // namespace popup::bindings
