#pragma once
#include <array>

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

constexpr int max_parameters = 8;

/// One motion mechanism on the card's central fold, its parameters in a flat array so the
/// annealing can step any of them; what each entry means per kind is motion_parameters.hpp's.
struct MotionMechanism {
    MotionKind kind = MotionKind::stationary;
    std::array<double, max_parameters> p{};
};

} // namespace popup::motion
