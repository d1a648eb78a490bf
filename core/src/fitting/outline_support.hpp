#pragma once
// What the two outline stages (fit_outlines, fit_depth_layers) share: the model placed on the
// card, a refusal's first error, and a cut part written down as a FittedProfile.
#include <string>

#include "popup/input/model_mesh.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/apply_profile.hpp"

namespace popup::outline_support {

/// `model` with every vertex taken through `m` (model units to card mm).
inline ModelMesh placed(const ModelMesh& model, const Eigen::Matrix4d& m)
{
    ModelMesh out;
    out.source = model.source;
    out.triangles = model.triangles;
    out.vertices.reserve(model.vertices.size());
    for (const Vec3& x : model.vertices)
        out.vertices.push_back(m.topLeftCorner<3, 3>() * x + m.topRightCorner<3, 1>());
    return out;
}

/// The message of the first error in `d`, or `otherwise`.
inline std::string first_error(const Diagnostics& d, const std::string& otherwise)
{
    for (const Diagnostic& x : d)
        if (x.severity == Severity::error)
            return x.message;
    return otherwise;
}

/// `fp`'s outline, holes and areas from the part `cut` as apply_profile left it.
inline void record_cut(FittedProfile& fp, const Patch& cut, const ProfileApplied& applied)
{
    for (const Vec3& x : cut.outer)
        fp.outer.push_back(applied.frame.to_frame(x));
    for (const Loop3& hole : cut.holes) {
        Loop2 h;
        for (const Vec3& x : hole)
            h.push_back(applied.frame.to_frame(x));
        fp.holes.push_back(h);
    }
    fp.area = applied.area_after;
    fp.area_before = applied.area_before;
}

} // namespace popup::outline_support
