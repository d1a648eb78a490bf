#include "model_mesh_bytes.hpp"

namespace popup {

void put_mesh(ByteWriter& w, const ModelMesh& mesh)
{
    w.put_all(mesh.vertices);
    w.put_all(mesh.triangles);
    w.put_all(mesh.colours);
    w.put_all(mesh.uvs);
    w.put_text(mesh.texture);
    w.put_all(mesh.texture_bytes);
    w.put_text(mesh.texture_format);
    w.put(mesh.texture_width);
    w.put(mesh.texture_height);
    w.put(mesh.base_colour);
}

void get_mesh(ByteReader& r, ModelMesh& mesh)
{
    r.get_all(mesh.vertices);
    r.get_all(mesh.triangles);
    r.get_all(mesh.colours);
    r.get_all(mesh.uvs);
    mesh.texture = r.get_text();
    r.get_all(mesh.texture_bytes);
    mesh.texture_format = r.get_text();
    mesh.texture_width = r.get<int>();
    mesh.texture_height = r.get<int>();
    mesh.base_colour = r.get<Vec3>();
}

} // namespace popup
