#include "popup/motion/animation.hpp"

namespace popup {

ModelMesh posed_mesh(const Animation& animation, double frame)
{
    ModelMesh posed = animation.mesh;
    if (animation.skin.size() != posed.vertices.size() ||
        animation.bind_inverse.size() != animation.bones.size())
        return posed;
    const std::vector<Eigen::Isometry3d> global = forward_kinematics(animation, frame);
    // Linear blend skinning: each vertex is the weighted mean of where its bones take it.
    std::vector<Eigen::Matrix4d> skinning(global.size());
    for (size_t b = 0; b < global.size(); ++b)
        skinning[b] = (global[b] * animation.bind_inverse[b]).matrix();
    for (size_t v = 0; v < posed.vertices.size(); ++v) {
        const Eigen::Vector4d rest = animation.mesh.vertices[v].homogeneous();
        Eigen::Vector4d sum = Eigen::Vector4d::Zero();
        for (const auto& [bone, weight] : animation.skin[v])
            sum += weight * (skinning[bone] * rest);
        posed.vertices[v] = sum.head<3>();
    }
    return posed;
}

} // namespace popup
