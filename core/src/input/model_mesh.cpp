#include "popup/input/model_mesh.hpp"

#include <cmath>
#include <sstream>

namespace popup {

double ModelMesh::area() const
{
    double total = 0.0;
    for (const auto& t : triangles)
        total +=
            0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
    return total;
}

double ModelMesh::diagonal() const
{
    if (vertices.empty())
        return 0.0;
    Vec3 lo = vertices.front(), hi = vertices.front();
    for (const Vec3& v : vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return (hi - lo).norm();
}

namespace {

std::string named(const ModelMesh& mesh)
{
    return mesh.source.empty() ? std::string("model") : mesh.source;
}

} // namespace

Result<ModelMesh> check_model(ModelMesh mesh)
{
    Result<ModelMesh> result;
    auto refuse = [&](DiagnosticCode code, const std::string& what) {
        result.fail(code, named(mesh) + ": " + what);
        return result;
    };
    if (mesh.triangles.empty())
        return refuse(DiagnosticCode::empty_model, "has no triangles (" +
                                                       std::to_string(mesh.vertices.size()) +
                                                       " vertices), must have at least one");
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!mesh.vertices[i].allFinite()) {
            std::ostringstream s;
            s << "vertex " << i << " = (" << mesh.vertices[i].x() << ", " << mesh.vertices[i].y()
              << ", " << mesh.vertices[i].z() << "), coordinates must be finite numbers";
            return refuse(DiagnosticCode::non_finite_model, s.str());
        }
    const int n = int(mesh.vertices.size());
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k : mesh.triangles[i])
            if (k < 0 || k >= n)
                return refuse(DiagnosticCode::degenerate_model,
                              "triangle " + std::to_string(i) + " uses vertex " +
                                  std::to_string(k) + ", must be in 0.." + std::to_string(n - 1));
    const double diagonal = mesh.diagonal();
    if (diagonal == 0.0)
        return refuse(DiagnosticCode::degenerate_model,
                      "every vertex lies at one point, a model needs an extent");
    if (diagonal < 1e-6 || diagonal > 1e6) {
        std::ostringstream s;
        s << "bounding-box diagonal = " << diagonal << " model units, must be in 1e-6..1e6";
        return refuse(DiagnosticCode::bad_model_size, s.str());
    }
    if (mesh.area() <= 1e-12 * diagonal * diagonal)
        return refuse(DiagnosticCode::degenerate_model,
                      "its triangles have no area (every vertex on one line or point)");
    result.value = std::move(mesh);
    return result;
}

} // namespace popup
