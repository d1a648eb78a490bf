#pragma once
// A deterministic mutation fuzzer for load_model: seed files written by assimp's Exporter (and an
// OFF by hand), mutated byte- and token-wise with a seeded std::mt19937_64, each read back.
// Whatever the bytes, load_model must come back: a checked mesh or a named error.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace popup::fixtures {

/// The seed files: a coloured tetrahedron and a cuboid in every format assimp writes that
/// load_model reads, written into `dir`.
std::vector<std::filesystem::path> write_seed_models(const std::filesystem::path& dir);

struct MutationRun {
    int reads = 0;                   ///< mutated files read
    int meshes = 0;                  ///< came back as a mesh
    int errors = 0;                  ///< came back as a named error
    int timeouts = 0;                ///< of those, readers stopped after timeout_s
    double slowest_s = 0.0;          ///< the longest read, timeouts included
    std::vector<std::string> broken; ///< what broke the contract, one line each (file: why)
};

/// `iterations` mutants of the seeds, written into `dir` (a mutant that breaks the contract is
/// kept there), each read with load_model under `timeout_s`. A mesh must have finite vertices,
/// triangles that index them and a non-zero area; an error must have a known code and name the
/// file.
MutationRun mutate_and_load(const std::vector<std::filesystem::path>& seeds, int iterations,
                            std::uint64_t seed, const std::filesystem::path& dir, double timeout_s);

} // namespace popup::fixtures
