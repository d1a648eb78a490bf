#pragma once
#include "popup/mechanisms/mechanism.hpp"

namespace popup {

/// Floating layer (parallel fold, thesis §2.3 and §4.3.5): a platform `height` above the open
/// host whose halves stay parallel to the host's patches at every fold angle (at height·sin(θ/2)
/// from them), on two supports standing `support` from the hinge; the platform overhangs each
/// support by `overhang`. Two step folds (support +
/// platform half) meet over the hinge on a backbone, and end panels keep the platform from
/// shearing (docs/MATH.md, Box fold). The platform is offered as a base patch pair.
struct FloatingLayerParams : Placement1D {
    double height = 25.0;   ///< h (mm)
    double support = 20.0;  ///< distance of each support from the host hinge (mm)
    double overhang = 15.0; ///< platform beyond each support (mm)
};

/// A floating layer's side pairs (offered as "<name>.side_ground" and "<name>.side_backdrop"):
/// the host's page outside a support and that support, hinged at `support` from the host hinge.
enum class LayerSide { ground, backdrop };

/// Closed form: the side pair `side` posed when the layer's host (built flat) is open at
/// `angle`, in the host's frame: the hinge at support·g(angle) (or b), y from the layer's offset,
/// `up` the bisector of the page and the support (which stays along the host's z), opening
/// angle/2. Patch ids and depths are left unset (the offered pair has them).
BasePatchPair floating_layer_side(const FloatingLayerParams& params, LayerSide side, double angle);

Result<MechanismParts> add_floating_layer(Scaffold& scaffold, const BasePatchPair& host,
                                          const FloatingLayerParams& params,
                                          const std::string& name = "FloatingLayer");

} // namespace popup
