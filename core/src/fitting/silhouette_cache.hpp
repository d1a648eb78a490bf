#pragma once
// Internal: the outline stage's silhouettes, one per direction of view. An orthographic
// silhouette depends only on the line it is seen along, not on where the plane lies nor which
// way it faces: a box fold's L and R, its four end panels, and TG with TB each see the same one,
// and so does every box standing square on the card. Projecting and uniting a model's triangles
// is most of the stage's time, so each is done once and moved into each part's frame.
#include <string>
#include <vector>

#include "popup/fitting/silhouette_types.hpp"
#include "popup/input/model_mesh.hpp"
#include "popup/model/profile.hpp"

namespace popup {

class SilhouetteCache {
public:
    /// `model` is in card mm and must outlive the cache.
    explicit SilhouetteCache(const ModelMesh& model) : model_(model) {}

    /// silhouette_profile's answer for a part whose frame (posed where the model is) is
    /// `frame`, titled `on` in its error: the model's silhouette along frame.normal in that
    /// frame. Computed in the frame of the first part seen along that line, then carried
    /// over by the rigid map between the two frames (a rotation, or a reflection when the
    /// normals are opposite, and a shift); on Clipper's grid the points agree to a nanometre.
    Result<Silhouette> seen_in(const ProfileFrame& frame, const std::string& on);

private:
    struct Seen {
        ProfileFrame frame; ///< where `silhouette` is drawn
        Silhouette silhouette;
    };
    const ModelMesh& model_;
    bool checked_ = false;
    std::vector<Seen> seen_;
};

} // namespace popup
