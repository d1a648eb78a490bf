#pragma once
// A model's silhouette on a patch's plane, as silhouette_profile and depth_layers return it;
// below them so that what makes one (projected_faces) does not include silhouette.hpp.
#include "popup/model/profile.hpp"

namespace popup {

/// What the model's orthographic silhouette on a patch's plane is made of.
struct Silhouette {
    Profile profile;       ///< the largest piece: outer loop and holes, in the profile frame
    double area = 0.0;     ///< mm², of that piece
    double left_out = 0.0; ///< mm², of the smaller pieces not in `profile`
    int pieces = 0;        ///< connected pieces of the whole silhouette
    int triangles = 0;     ///< triangles projected (after the depth window)
};

} // namespace popup
