#pragma once
#include <optional>
#include <string>
#include <vector>

namespace popup {

// Every machine code a diagnostic can carry, in one list: the enumeration, its names and the
// documented table (docs/DIAGNOSTICS.md, checked by a test) all come from here.
#define POPUP_DIAGNOSTIC_CODES(X)                                                                  \
    /* design files and scaffolds */                                                               \
    X(unreadable_file)                                                                             \
    X(bad_json)                                                                                    \
    X(bad_field)                                                                                   \
    X(empty_scaffold)                                                                              \
    X(too_few_vertices)                                                                            \
    X(non_finite_coordinate)                                                                       \
    X(repeated_vertex)                                                                             \
    X(duplicate_patch_id)                                                                          \
    X(degenerate_patch)                                                                            \
    X(non_planar_patch)                                                                            \
    X(self_crossing_outline)                                                                       \
    X(hole_crosses_outline)                                                                        \
    X(hole_outside_outline)                                                                        \
    X(holes_overlap)                                                                               \
    X(base_patch_misplaced)                                                                        \
    X(missing_base_patch)                                                                          \
    X(bad_design_angle)                                                                            \
    X(bad_paper_thickness)                                                                         \
    X(duplicate_hinge_id)                                                                          \
    X(bad_hinge_patches)                                                                           \
    X(degenerate_hinge)                                                                            \
    X(hinge_off_patch)                                                                             \
    X(duplicate_slit_id)                                                                           \
    X(bad_slit_patches)                                                                            \
    X(degenerate_slit)                                                                             \
    X(slit_off_patch)                                                                              \
    X(slit_off_plane)                                                                              \
    X(bad_glue_patches)                                                                            \
    X(base_glued)                                                                                  \
    X(bases_not_hinged)                                                                            \
    X(detached_patch)                                                                              \
    /* mechanisms */                                                                               \
    X(bad_parameter)                                                                               \
    X(bad_host)                                                                                    \
    X(mechanism_does_not_fit)                                                                      \
    X(design_error)                                                                                \
    /* simulation and validity */                                                                  \
    X(bad_option)                                                                                  \
    X(angle_out_of_range)                                                                          \
    X(bad_start_state)                                                                             \
    X(motion_locked)                                                                               \
    X(branch_not_followed)                                                                         \
    X(undirected_flat_fold)                                                                        \
    X(not_flat_when_closed)                                                                        \
    X(unstable)                                                                                    \
    X(intersection)                                                                                \
    X(not_enclosed)                                                                                \
    X(enclosure_unknown)                                                                           \
    /* models and automatic design (fitting) */                                                    \
    X(unreadable_model)                                                                            \
    X(unreadable_texture)                                                                          \
    X(empty_model)                                                                                 \
    X(non_finite_model)                                                                            \
    X(degenerate_model)                                                                            \
    X(bad_model_size)                                                                              \
    X(mechanism_dropped)                                                                           \
    X(no_design_found)                                                                             \
    /* animations: motion from an animated character */                                            \
    X(bad_animation)                                                                               \
    X(skeleton_cycle)                                                                              \
    X(no_animation)                                                                                \
    X(single_frame)                                                                                \
    X(non_finite_animation)                                                                        \
    /* profiles: outlines on patches */                                                            \
    X(bad_profile)                                                                                 \
    X(profile_misses_hinge)                                                                        \
    /* pieces and cutting sheets */                                                                \
    X(empty_piece)                                                                                 \
    X(unknown_patch)                                                                               \
    X(disconnected_piece)                                                                          \
    X(not_developable)                                                                             \
    X(not_flat)                                                                                    \
    X(flat_fold)                                                                                   \
    X(piece_overlaps_itself)                                                                       \
    X(glue_without_tab)                                                                            \
    X(piece_falls_apart)                                                                           \
    X(kerf_closes_opening)                                                                         \
    X(detached_piece)                                                                              \
    X(no_room_for_tab)                                                                             \
    X(narrow_tab)                                                                                  \
    X(narrow_feature)                                                                              \
    X(sharp_corner)                                                                                \
    X(round_trip_unplaced)                                                                         \
    X(round_trip_failed)                                                                           \
    X(round_trip_mismatch)                                                                         \
    X(drawing_unusable)                                                                            \
    X(unlabelled_piece)                                                                            \
    X(missing_piece)                                                                               \
    X(outline_mismatch)                                                                            \
    X(fold_missing)                                                                                \
    X(fold_misplaced)                                                                              \
    X(fold_extra)                                                                                  \
    X(fold_direction_wrong)                                                                        \
    X(fold_not_separating)                                                                         \
    X(tab_unmatched)                                                                               \
    X(tab_wrong_target)                                                                            \
    X(joint_without_tab)                                                                           \
    X(bad_paper)                                                                                   \
    X(bad_margin)                                                                                  \
    X(bad_spacing)                                                                                 \
    X(bad_shape)                                                                                   \
    X(piece_does_not_fit)

enum class DiagnosticCode {
#define POPUP_DIAGNOSTIC_ENUMERATOR(name) name,
    POPUP_DIAGNOSTIC_CODES(POPUP_DIAGNOSTIC_ENUMERATOR)
#undef POPUP_DIAGNOSTIC_ENUMERATOR
};

/// The code's name, as written in JSON and seen in Python ("bad_parameter").
const char* to_string(DiagnosticCode code);
/// Every code, in declaration order.
const std::vector<DiagnosticCode>& all_diagnostic_codes();
/// The code named `name`, if there is one.
std::optional<DiagnosticCode> diagnostic_code_named(const std::string& name);

} // namespace popup
