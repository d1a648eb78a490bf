#include "silhouette_cache.hpp"

#include <cmath>

#include "projected_faces.hpp"

namespace popup {

namespace {

/// `loop` drawn in `from`, redrawn in `to` (the two frames' planes parallel).
Loop2 moved(const Loop2& loop, const ProfileFrame& from, const ProfileFrame& to)
{
    Loop2 out;
    out.reserve(loop.size());
    for (const Vec2& q : loop)
        out.push_back(to.to_frame(from.to_world(q)));
    return out;
}

} // namespace

Result<Silhouette> SilhouetteCache::seen_in(const ProfileFrame& frame, const std::string& on)
{
    Result<Silhouette> r;
    if (!checked_) {
        const Result<ModelMesh> checked = check_model(model_);
        if (!checked.ok) {
            r.fail_with(checked.diagnostics);
            return r;
        }
        checked_ = true;
    }
    const Seen* found = nullptr;
    for (const Seen& s : seen_)
        if (std::abs(s.frame.normal.dot(frame.normal)) >= 1.0 - 1e-12) {
            found = &s;
            break;
        }
    if (!found) {
        const std::vector<ProjectedFace> faces =
            project_faces(model_, frame, std::nullopt, std::nullopt, false);
        std::vector<const ProjectedFace*> all;
        all.reserve(faces.size());
        for (const ProjectedFace& f : faces)
            all.push_back(&f);
        seen_.push_back({frame, unite_faces(all, "silhouette of the model")});
        found = &seen_.back();
    }
    r.value = found->silhouette;
    r.value.profile.name =
        "silhouette of " + (model_.source.empty() ? "the model" : model_.source) + " on " + on;
    if (!(r.value.area > 0)) {
        r.fail(DiagnosticCode::bad_option,
               r.value.profile.name + " is empty: no face of the model lies in the depth window "
                                      "or faces that patch",
               about_patches({frame.patch}));
        return r;
    }
    if (found->frame.origin != frame.origin || found->frame.u != frame.u ||
        found->frame.v != frame.v) {
        r.value.profile.outer = moved(r.value.profile.outer, found->frame, frame);
        for (Loop2& h : r.value.profile.holes)
            h = moved(h, found->frame, frame);
    }
    return r;
}

} // namespace popup
