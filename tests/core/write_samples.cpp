// Writes the bundled design files from their builders:
//   popup_write_samples <repo root>
// -> resources/samples/demo_card.json and tests/data/*.json. The test SampleFiles.* checks the
// committed files still match, so edit the builders, not the files.
#include <iostream>

#include "popup/io/design_file.hpp"
#include "sample_files.hpp"

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: popup_write_samples <repo root>\n";
        return 2;
    }
    for (const auto& sample : popup::fixtures::sample_files()) {
        const std::string path = std::string(argv[1]) + "/" + sample.path;
        popup::save_scaffold(sample.scaffold, path);
        std::cout << path << "\n";
    }
    return 0;
}
