#include "popup/fitting/silhouette.hpp"

#include <sstream>

#include "projected_faces.hpp"

namespace popup {

Result<Silhouette> silhouette_profile(const ModelMesh& model, const Scaffold& scaffold,
                                      int patch_id, const SilhouetteOptions& options)
{
    Result<Silhouette> r;
    const Result<ModelMesh> checked = check_model(model);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    if (options.depth_near && options.depth_far && !(*options.depth_near < *options.depth_far)) {
        std::ostringstream m;
        m << "silhouette: depth window [" << *options.depth_near << ", " << *options.depth_far
          << "] mm is empty, depth_near must be below depth_far";
        r.fail(DiagnosticCode::bad_option, m.str(), about_parameter("depth_near"));
        return r;
    }
    const Result<ProfileFrame> frame = profile_frame(scaffold, patch_id);
    if (!frame.ok) {
        r.fail_with(frame.diagnostics);
        return r;
    }
    const Patch* patch = scaffold.find_patch(patch_id);
    const std::string on = patch->name.empty() ? "patch " + std::to_string(patch_id) : patch->name;
    const std::vector<ProjectedFace> faces =
        project_faces(model, posed(frame.value, options.pose), options.depth_near,
                      options.depth_far, options.facing_only);
    std::vector<const ProjectedFace*> all;
    for (const ProjectedFace& f : faces)
        all.push_back(&f);
    r.value = unite_faces(
        all, "silhouette of " + (model.source.empty() ? "the model" : model.source) + " on " + on);
    if (!(r.value.area > 0)) {
        r.fail(DiagnosticCode::bad_option,
               r.value.profile.name + " is empty: no face of the model lies in the depth window "
                                      "or faces that patch",
               about_patches({patch_id}));
    }
    return r;
}

} // namespace popup
