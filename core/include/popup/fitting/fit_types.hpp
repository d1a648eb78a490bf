#pragma once
// The data of the fitting pipeline (thesis §5.1): what the maker chooses and what comes back.
// Below the driver (fit_design.hpp), so no stage includes the driver.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "popup/fitting/supporting_plate.hpp"
#include "popup/mechanisms/designed_card.hpp"
#include "popup/model/card.hpp"
#include "popup/model/result.hpp"
#include "popup/model/scaffold.hpp"
#include "popup/model/stage_timings.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup {

/// What the maker chooses for an automatic design from a model (thesis §5.1).
struct FitOptions {
    std::optional<Vec3> up; ///< model direction that becomes the card's z; default: NPCA
    /// Model direction that faces the viewer: it becomes the card's +x, the ground side the
    /// viewer stands on. Default: the normal of the model's mirror plane containing `up`.
    std::optional<Vec3> facing;
    CardParams card;     ///< its width along the central fold and depth (mm), from the paper
    double margin = 0.1; ///< free border of the card, fraction of each card dimension
    int max_mechanisms = 8;
    /// Smallest primitive worth finding: a cube of this edge, as a fraction of the model's
    /// diagonal (τ; in samples, its five visible faces: docs/MATH.md, Fitting).
    double min_shape = 0.05;
    double probability = 0.99; ///< stop when no better primitive was overlooked with this P
    double threshold = 0.02;   ///< point-to-primitive tolerance, fraction of the diagonal
    int samples = 20000;       ///< pseudo-vertices spread over the surface
    /// Shortest glued crease a primitive may make (mm, on the card): its length along the hinge
    /// and, for a box fold, its depths and height (prism_ransac.cpp, thick_enough). Thinner
    /// primitives are not accepted. Default: the shortest crease on which the default cutting
    /// sheets always place their narrowest glue tab (shortest_tabbed_crease, ≈ 11.1 mm); 0 turns
    /// the rule off.
    double min_part_mm = shortest_tabbed_crease(SheetOptions{});
    std::uint64_t seed = 1;
    /// Principal patches take the model's silhouette as a Profile (§5.1.3, fit_outlines.hpp).
    bool outlines = true;
    /// Box folds' front, back and top faces split into depth layers, each nearer layer a nested
    /// mechanism kept when the design stays valid and the model-to-pop-up mean distance drops
    /// (§5.1.3, fit_depth_layers.hpp). Needs `outlines`.
    bool depth_layers = true;
};

/// One fitted primitive, in the card's frame at the design state (mm), for previews.
struct FittedPrimitive {
    std::string kind;          ///< "rectangular" or "triangular"
    std::vector<Vec3> corners; ///< 8 for a rectangular prism, 6 for a triangular one
    std::string host;          ///< base patch pair it stands on
    int inliers = 0;
};

/// One depth layer of a box fold's front or top (§5.1.3) and what became of it.
struct FittedDepthLayer {
    std::string box;             ///< the box fold whose face it is in front of (B1...)
    std::string face;            ///< "front" (the box's L) or "top" (TG and TB)
    double depth = 0.0;          ///< mm in front of (above) that face: the area-weighted mean
    double area = 0.0;           ///< mm², of its silhouette on the box's face, clipped to the host
    bool kept = false;           ///< built as `mechanism`
    std::string mechanism;       ///< the nested mechanism (S2, B3...), or empty when never built
    std::string reason;          ///< why it was kept or dropped
    double mean_before_mm = 0.0; ///< model-to-pop-up mean distance before trying it (0: not
    double mean_after_mm = 0.0;  ///< measured) and with it
};

struct FitResult {
    CardParams card;
    Eigen::Matrix4d model_to_card = Eigen::Matrix4d::Identity(); ///< model units to card mm
    std::vector<FittedPrimitive> primitives;
    std::vector<FittedMechanism> mechanisms; ///< hosts before the mechanisms they carry
    std::vector<FitRepair> repairs;
    Scaffold scaffold; ///< card plus mechanisms at the design state (180°), profiled
    std::vector<FittedProfile> profiles; ///< outlines of the principal parts (options.outlines)
    std::vector<FittedDepthLayer> depth_layers; ///< options.depth_layers: every layer tried
    bool valid = false;    ///< the simulator's full validity check passed on `scaffold`
    double coverage = 0.0; ///< fraction of the pseudo-vertices within threshold of the pop-up
    StageTimings timings;  ///< each stage's seconds, in order, and the whole call's
    /// Warnings (mechanism_dropped, one per repair that dropped something) and, when no design
    /// passed, the last validity check's findings.
    Diagnostics diagnostics;
    double coverage_error = 1.0; ///< thesis eq. 5.1 over the returned mechanisms
    double symmetry_error = 0.0; ///< mean mirrored-sample distance / the model's diagonal
    long ransac_draws = 0;       ///< minimal samples drawn by the primitive search
    /// The plate under the model (a terrain slab, a print bed) that became the card's page;
    /// the pop-up shows what stands on it, and is measured against that (above_plate).
    std::optional<SupportingPlate> plate;
    /// Pseudo-vertices of the search above the plate: on the outer surface, and inside the
    /// model's volume (faces between touching parts, a box's top under its roof, inner parts,
    /// window reveals: they may carry a prism's face but never refuse one); and the model's
    /// triangles turned to face out of its volume (docs/MATH.md, "The model's volume").
    int outer_samples = 0, inner_samples = 0, turned_faces = 0;

    /// `valid` with at least one mechanism on the card: a bare card is no pop-up, so no
    /// design is made of it and no sheets are cut.
    bool pops_up() const { return valid && !mechanisms.empty(); }
};

} // namespace popup
