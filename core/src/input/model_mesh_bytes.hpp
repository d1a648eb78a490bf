#pragma once
// A ModelMesh as plain bytes, for the reading child processes (load_model, load_animation).
#include "byte_message.hpp"
#include "popup/input/model_mesh.hpp"

namespace popup {

void put_mesh(ByteWriter& writer, const ModelMesh& mesh);
/// Reads what put_mesh wrote (the reader's `fine` says whether it was all there).
void get_mesh(ByteReader& reader, ModelMesh& mesh);

} // namespace popup
