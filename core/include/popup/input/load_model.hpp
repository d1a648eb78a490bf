#pragma once
#include <string>

#include "popup/input/model_mesh.hpp"
#include "popup/model/result.hpp"

namespace popup {

struct LoadModelOptions {
    /// The reader runs in a child process stopped after this long (a malformed file can make
    /// assimp loop forever).
    double timeout_s = 120.0;
};

/// Reads a mesh file through assimp (OBJ, STL ASCII and binary, PLY, OFF, glTF/GLB, FBX, Collada,
/// 3MF, and whatever else assimp reads) into one triangle mesh in the file's units: the node
/// hierarchy flattened with every node transform applied, polygons triangulated, identical
/// vertices joined, points and lines dropped. Appearance: vertex colours (first set), texture
/// coordinates (first channel), the first base-colour or diffuse texture (a path joined to the
/// model's folder, or an embedded image's bytes) and the diffuse colour of the largest material;
/// materials of different colours without vertex colours become per-vertex colours. The texture
/// is decoded once in the reader (read_model_texture): one that cannot be (a missing file,
/// corrupt bytes, a format stb_image does not read) is an unreadable_texture warning naming the
/// model and the texture, and the mesh still loads, its texture fields as the file gave them.
/// assimp runs in a child process (fork), so a file that makes it abort or hang is an error,
/// not the end of the caller. Errors: non_finite_model naming the vertex, its line and the token
/// when a text file (OBJ, ASCII STL, ASCII PLY, OFF) writes a coordinate as NaN, infinity or
/// beyond single precision (checked before assimp, which reads "nan" as a finite number);
/// unreadable_model naming the path and assimp's message (or
/// the crash, or the timeout), then check_model's.
Result<ModelMesh> load_model(const std::string& path, const LoadModelOptions& options = {});

} // namespace popup
