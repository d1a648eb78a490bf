#include "bvh_root_channels.hpp"

#include <fstream>
#include <sstream>

namespace popup::motion {

std::string bvh_position_only_root(const std::string& path)
{
    std::ifstream in(path);
    std::string word, root;
    // The header's words in order: ROOT name { OFFSET x y z CHANNELS n names...; only the
    // root's first CHANNELS line matters, and nothing past MOTION is read.
    while (in >> word) {
        if (word == "MOTION")
            return {};
        if (word == "ROOT") {
            if (!(in >> root))
                return {};
            continue;
        }
        if (word != "CHANNELS" || root.empty())
            continue;
        int count = 0;
        if (!(in >> count) || count != 3)
            return {};
        for (int k = 0; k < count; ++k) {
            std::string channel;
            if (!(in >> channel) || channel.find("position") == std::string::npos)
                return {};
        }
        return root;
    }
    return {};
}

} // namespace popup::motion
