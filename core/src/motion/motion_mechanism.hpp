#pragma once
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"

namespace popup::motion {

/// The mappings of thesis Table 6.1, plus the floating layer for a chain that does not move.
enum class MotionKind { vertical, diagonal, horizontal, rotation, stationary };
constexpr int motion_kind_count = 5;
const char* to_string(MotionKind kind); ///< "vertical", ..., "stationary" (ChainReport::mapping)

/// How the annealing steps a parameter (thesis §6.4.3): angles by 10°, lengths by 1/20 of the
/// character's diagonal, positions (the anchor along the fold and across it) by 1/50.
enum class ParameterRole { angle, length, position };

struct ParameterInfo {
    const char* name; ///< the library's params-struct field
    ParameterRole role;
};

// Each kind's parameters, in the library's params structs (mm and radians). What the search
// steps of them, in which order, is parameter_table.cpp's.

/// Vertical translation (add_vertical_translation): the thesis's half v-box, without back walls.
struct VerticalMotion : VBoxFoldParams {
    VerticalMotion() { back = false; }
};

/// Diagonal translation (thesis §4.3.3): a v-fold whose spine stands at 180°, and a step fold on
/// its wings (add_v_fold, then add_step_fold on its offered pair). step.offset is along the
/// spine.
struct DiagonalMotion {
    VFoldParams v_fold;
    StepFoldParams step;

    DiagonalMotion() { v_fold.spine_angle = M_PI / 2; }
};

/// Horizontal translation (add_horizontal_translation).
struct HorizontalMotion : HorizontalTranslationParams {};

/// Rotation (add_rotation_arm) on the central fold (hinge 0), or on the side pair of a floating
/// layer (thesis §4.3.4, last paragraph: a rotation off the fold): ±hinge on the ground (+) or
/// backdrop (−) pair of a layer with supports |hinge| from the fold, as wide as the spine, from
/// `offset`, its height rotation_layer_height. `offset` is along the central fold either way:
/// the arm's start on the fold, or its layer's (on the side pair the arm starts at 0:
/// rotation_params).
struct RotationMotion : RotationArmParams {
    double hinge = 0.0;
};

/// A still part on a floating layer (add_floating_layer): `anchor` is the platform point, across
/// the fold (+ ground, − backdrop), that carries the part.
struct StationaryMotion : FloatingLayerParams {
    double anchor = 0.0;
};

/// One motion mechanism on the card's central fold: its kind's parameters, by name
/// (m.rotation().arm). The search steps them by index through parameter_table.hpp.
struct MotionMechanism {
    /// In MotionKind's order: the alternative's index is the kind.
    using Params = std::variant<VerticalMotion, DiagonalMotion, HorizontalMotion, RotationMotion,
                                StationaryMotion>;
    Params params = StationaryMotion{};

    MotionKind kind() const { return MotionKind(params.index()); }

    VerticalMotion& vertical() { return as<VerticalMotion>(MotionKind::vertical); }
    DiagonalMotion& diagonal() { return as<DiagonalMotion>(MotionKind::diagonal); }
    HorizontalMotion& horizontal() { return as<HorizontalMotion>(MotionKind::horizontal); }
    RotationMotion& rotation() { return as<RotationMotion>(MotionKind::rotation); }
    StationaryMotion& stationary() { return as<StationaryMotion>(MotionKind::stationary); }
    const VerticalMotion& vertical() const { return as<VerticalMotion>(MotionKind::vertical); }
    const DiagonalMotion& diagonal() const { return as<DiagonalMotion>(MotionKind::diagonal); }
    const HorizontalMotion& horizontal() const
    {
        return as<HorizontalMotion>(MotionKind::horizontal);
    }
    const RotationMotion& rotation() const { return as<RotationMotion>(MotionKind::rotation); }
    const StationaryMotion& stationary() const
    {
        return as<StationaryMotion>(MotionKind::stationary);
    }

private:
    template <class Motion> Motion& as(MotionKind wanted)
    {
        return const_cast<Motion&>(std::as_const(*this).as<Motion>(wanted));
    }
    template <class Motion> const Motion& as(MotionKind wanted) const
    {
        if (const Motion* motion = std::get_if<Motion>(&params))
            return *motion;
        throw std::logic_error(std::string("motion mechanism: its ") + to_string(wanted) +
                               " parameters asked for, but it is a " + to_string(kind()));
    }
};

/// The parameters of the kind `kind`.
template <MotionKind kind>
using MotionOf = std::variant_alternative_t<int(kind), MotionMechanism::Params>;
static_assert(std::is_same_v<MotionOf<MotionKind::vertical>, VerticalMotion> &&
                  std::is_same_v<MotionOf<MotionKind::diagonal>, DiagonalMotion> &&
                  std::is_same_v<MotionOf<MotionKind::horizontal>, HorizontalMotion> &&
                  std::is_same_v<MotionOf<MotionKind::rotation>, RotationMotion> &&
                  std::is_same_v<MotionOf<MotionKind::stationary>, StationaryMotion> &&
                  std::variant_size_v<MotionMechanism::Params> == motion_kind_count,
              "MotionMechanism::Params lists the kinds in MotionKind's order");

} // namespace popup::motion
