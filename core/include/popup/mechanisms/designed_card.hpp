#pragma once
// What an automatic design hands the workbench, whichever pipeline made it (a model's fit or an
// animation's motion): the mechanisms to build, the changes made on the way, the parts' outlines.
// Below both pipelines, so motion does not include fitting's driver.
#include <string>
#include <vector>

#include "popup/mechanisms/designed_mechanism.hpp"
#include "popup/model/profile.hpp"

namespace popup {

/// One mechanism of the result: what a FreeCAD feature of its kind needs to be made, and what
/// it stands for.
struct FittedMechanism : DesignedMechanism {
    std::string primitive;       ///< what it maps, e.g. "rectangular prism 2"
    double coverage_error = 0.0; ///< thesis eq. 5.1 for its primitive
};

/// A mechanism the pipeline left out or changed, and why.
struct FitRepair {
    std::string mechanism;
    /// "shrunk", "trimmed", "re-hosted", "dropped" (the validity repair, docs/DESIGN.md),
    /// "remapped", "replaced" (by the bulk box), "profile dropped", "layer kept"/"layer dropped"
    std::string action;
    std::string reason;
};

/// A principal part's outline from the model (§5.1.3): what popupwb.profiles.set_profile stores.
struct FittedProfile {
    std::string mechanism; ///< B1, T1...
    std::string part;      ///< TG, L, riser, slope_ground...
    Loop2 outer;           ///< the profiled patch's outline in the part's profile frame (mm)
    std::vector<Loop2> holes;
    Vec2 reference = Vec2::Zero(); ///< the part's size as generated (extent along u, v; mm)
    double area = 0.0;             ///< mm², of the profiled patch
    double area_before = 0.0;      ///< mm², of the part as generated
};

} // namespace popup
