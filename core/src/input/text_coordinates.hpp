#pragma once
// Internal: vertex coordinates of text mesh files read by our own scanner, because assimp 5.2's
// number parser turns some spellings of NaN and infinity ("nan", "inf", "-nan") into finite
// numbers, and the error would then be about area or size instead of the NaN.
#include <optional>
#include <string>

namespace popup {

struct NonFiniteCoordinate {
    long line = 0;     ///< 1-based line of the file
    long vertex = 0;   ///< 0-based vertex index in the file's vertex list
    char axis = 'x';   ///< 'x', 'y' or 'z'
    std::string token; ///< the coordinate as written
};

/// The first vertex coordinate of an OBJ ("v" lines), ASCII STL ("vertex" lines), ASCII PLY
/// (the x, y, z properties of the vertex element) or OFF file that is NaN, infinite, or beyond
/// single precision (assimp stores floats, so it would become infinite). Files of other formats,
/// binary files and unreadable files give nullopt: assimp and check_model judge those.
std::optional<NonFiniteCoordinate> find_non_finite_coordinate(const std::string& path);

} // namespace popup
