#pragma once
#include <array>
#include <string>
#include <vector>

#include "popup/geometry/pose.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// A triangle mesh given as the model of a pop-up (thesis §5.1): coordinates in the model's own
/// units, taken as mm. Appearance is optional and per vertex, as assimp delivers it: a vertex
/// whose colour or texture coordinate differs on two faces is two vertices.
struct ModelMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles; ///< counter-clockwise seen from outside
    std::vector<Vec3> colours;                 ///< empty, or one RGB in [0, 1] per vertex
    /// Empty, or one texture coordinate per vertex; NaN for a vertex whose material does not
    /// use `texture` (a model with several materials), whose colour is in `colours` then.
    std::vector<Vec2> uvs;
    std::string texture; ///< path of the base colour image, or "*N" for an embedded one, or empty
    /// An embedded base colour image (GLB, FBX): the file's bytes as stored (`texture_format` is
    /// its extension, "png", "jpg"), or, when `texture_width` > 0, raw RGBA8 texels row by row.
    std::vector<unsigned char> texture_bytes;
    std::string texture_format;
    int texture_width = 0;
    int texture_height = 0;
    Vec3 base_colour = Vec3(0.8, 0.8, 0.8); ///< the material's diffuse colour
    std::string source;                     ///< file or object name, for messages

    double area() const;
    /// Diagonal of the axis-aligned bounding box (0 for an empty mesh).
    double diagonal() const;
};

/// Refuses a mesh nothing can be made of, naming the source and what is wrong: no triangles, a
/// NaN or infinite coordinate (naming the vertex), an index out of range, every vertex at one
/// point, or a size outside [1e-6, 1e6] model units. Returns the mesh unchanged otherwise.
Result<ModelMesh> check_model(ModelMesh mesh);

} // namespace popup
