#pragma once
#include <optional>

#include "popup/fitting/silhouette_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/profile.hpp"

namespace popup {

struct SilhouetteOptions {
    /// Keep only the model between these depths (mm along the patch's normal from its plane,
    /// positive on its printed side); triangles are cut at the window's planes, not dropped.
    std::optional<double> depth_near; ///< lower end of the window
    std::optional<double> depth_far;  ///< upper end of the window
    /// Only triangles facing the patch's printed side (normal · patch normal > 0). A closed mesh
    /// has the same silhouette either way, with half the triangles.
    bool facing_only = false;
    /// Where the patch is when the model is where it is: its pose from the design state (a
    /// step's riser stands only when the card is open at 90°: pass its pose there, from
    /// simulate_fold). The profile stays in the patch's own frame, which moves with it.
    std::optional<Pose> pose;
};

/// The orthographic silhouette of `model` (card frame, mm: the model already placed on the card)
/// on the plane of patch `patch_id`, in that patch's profile frame (docs/DESIGN.md, Profiles):
/// every triangle projected along the patch's normal and all of them united exactly (Clipper,
/// nanometre grid; no raster, so a wheel keeps its polygon). Ready for apply_profile, which clips
/// it to what the mechanism allows. Fails (unknown_patch, bad_profile) for a patch without a
/// frame, and (bad_option) for an empty window or a silhouette with no area; check_model's
/// errors for a bad model.
Result<Silhouette> silhouette_profile(const ModelMesh& model, const Scaffold& scaffold,
                                      int patch_id, const SilhouetteOptions& options = {});

} // namespace popup
