#pragma once
#include <string>

namespace popup::motion {

/// The name of a BVH file's ROOT joint when its CHANNELS line declares only the three position
/// channels (no rotation), else empty. assimp 5.2 reads such a root without its motion (the root
/// stays at its OFFSET whatever the frames say), so the loader refuses the file rather than
/// design a character that stands still. Reads the HIERARCHY header only.
std::string bvh_position_only_root(const std::string& path);

} // namespace popup::motion
