#pragma once
#include <string>
#include <vector>

#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

struct SampleFile {
    std::string path; ///< relative to the repository root
    Scaffold scaffold;
};

/// Every design file the repository ships, with the builder it comes from.
std::vector<SampleFile> sample_files();

} // namespace popup::fixtures
