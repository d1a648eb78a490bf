// `make fuzz`'s load_model driver: load_model_fuzz [--iterations N] [--seed S] [--dir DIR]
// [--timeout SECONDS]. Writes the seed models into DIR, reads N mutants of them and lists every
// mutant that broke the contract (kept in DIR). Exit 0 when none did, 1 otherwise, 2 on bad use.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "load_model_mutations.hpp"

int main(int argc, char** argv)
{
    int iterations = 2000;
    unsigned long long seed = 1;
    double timeout_s = 5.0;
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "popup_load_model_fuzz";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "load_model_fuzz: %s needs a value\n", arg.c_str());
            return 2;
        }
        const char* value = argv[++i];
        if (arg == "--iterations")
            iterations = std::atoi(value);
        else if (arg == "--seed")
            seed = std::strtoull(value, nullptr, 10);
        else if (arg == "--dir")
            dir = value;
        else if (arg == "--timeout")
            timeout_s = std::atof(value);
        else {
            std::fprintf(stderr, "load_model_fuzz: unknown option %s\n", arg.c_str());
            return 2;
        }
    }
    if (iterations < 0 || !(timeout_s > 0.0)) {
        std::fprintf(stderr, "load_model_fuzz: --iterations must be >= 0, --timeout > 0\n");
        return 2;
    }
    std::filesystem::remove_all(dir);
    const auto seeds = popup::fixtures::write_seed_models(dir);
    const popup::fixtures::MutationRun run =
        popup::fixtures::mutate_and_load(seeds, iterations, seed, dir, timeout_s);
    std::printf("load_model_fuzz: %zu seeds, %d mutants read (seed %llu): %d meshes, %d named "
                "errors (%d timed out), %zu broken; slowest read %.2f s\n",
                seeds.size(), run.reads, seed, run.meshes, run.errors, run.timeouts,
                run.broken.size(), run.slowest_s);
    for (const std::string& line : run.broken)
        std::printf("  %s\n", line.c_str());
    return run.broken.empty() ? 0 : 1;
}
