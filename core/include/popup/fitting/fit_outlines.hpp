#pragma once
#include <string>
#include <vector>

#include "popup/input/model_mesh.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup {

/// The parts of a mechanism of `kind` that take the model's outline (thesis Fig 5.3,
/// the shaded principal faces; §5.1.3): box fold L, R, TG, TB and its end panels (FL, FR, BL,
/// BR, numbered when stacked), tent fold both slopes, step fold riser and tread, v-fold both
/// wings. Part-name prefixes; a mechanism's patches whose part starts with one of them qualify.
std::vector<std::string> principal_parts(MechanismKind kind);

/// What the outline stage did.
struct OutlineOutcome {
    Scaffold scaffold;                   ///< the design with the kept profiles applied
    std::vector<FittedProfile> profiles; ///< kept, in scaffold patch order
    std::vector<FitRepair> dropped;      ///< {mechanism, "profile dropped", "PART: why"}
};

/// §5.1.3: every principal part of `mechanisms` (as built in `scaffold`, a valid design at 180°)
/// takes the orthographic silhouette of `model_in_card` (the model already in card mm) on its
/// plane, posed where the part stands as the model does (a step flat at 180° is posed at 90°),
/// clipped to the part by apply_profile. A mechanism's profiles are applied together and kept
/// when the full check_validity still passes; otherwise each is tried alone, in patch order, and
/// the ones that break validity (or that apply_profile refuses) are dropped and reported. A
/// part whose silhouette covers it whole keeps no profile (a stored outline would clip later
/// edits of its dimensions); a part carrying a later mechanism keeps one only when that
/// mechanism's folds on it stay whole (the workbench cuts a part before it builds on it). Along
/// each glued joint the silhouette still meets, the outline keeps a strip of paper the default
/// tab width deep over that stretch, lengthened to `glued_joint_mm` where shorter (by default
/// the default sheets' shortest tabbed crease, as FitOptions::min_part_mm; a crease shared with
/// another glued joint is kept whole), so the sheets can glue it (docs/DESIGN.md, "Outlines that
/// follow the model"). An outline that would still leave a piece of a glued joint shorter than
/// `glued_joint_mm`, or the part short of the default tab width inward along such a joint, is
/// dropped; 0 keeps no strips and checks neither.
OutlineOutcome fit_outlines(const ModelMesh& model_in_card, const Scaffold& scaffold,
                            const std::vector<FittedMechanism>& mechanisms,
                            const CancelFlag* cancel = nullptr,
                            double glued_joint_mm = shortest_tabbed_crease(SheetOptions{}));

/// fit_outlines for one mechanism whose outlined parts are `parts` (part-name prefixes, as
/// principal_parts gives them) instead of its type's principal parts, posed at the design state
/// (180°). The motion design outlines each moving patch with its own body part this way,
/// with the same strips along glued joints and the same checks.
OutlineOutcome fit_outlines_of(const ModelMesh& model_in_card, const Scaffold& scaffold,
                               const FittedMechanism& mechanism,
                               const std::vector<std::string>& parts,
                               const CancelFlag* cancel = nullptr);

/// The same for `model` in its own units, placed on the card by `model_to_card` first.
OutlineOutcome fit_outlines_for(const ModelMesh& model, const Eigen::Matrix4d& model_to_card,
                                const Scaffold& scaffold,
                                const std::vector<FittedMechanism>& mechanisms,
                                const CancelFlag* cancel = nullptr,
                                double glued_joint_mm = shortest_tabbed_crease(SheetOptions{}));

} // namespace popup
