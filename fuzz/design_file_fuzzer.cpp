// libFuzzer target 1: the JSON design-file reader (popup::scaffold_from_json) on arbitrary text.
// Every input must end in a Result (a scaffold or named errors), never a crash, a leak, undefined
// behaviour or an escaping exception. A design that reads back must also survive a round trip:
// written by scaffold_to_json and read again, it is still accepted with the same patches and
// hinges.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "popup/io/design_file.hpp"

namespace {

[[noreturn]] void fail(const char* what, const popup::Result<popup::Scaffold>& r)
{
    std::fprintf(stderr, "design_file_fuzzer: %s\n", what);
    for (const popup::Diagnostic& d : r.diagnostics)
        std::fprintf(stderr, "  %s\n", d.message.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    const popup::Result<popup::Scaffold> read = popup::scaffold_from_json(text);
    if (!read.ok) {
        if (read.diagnostics.empty())
            fail("refused without a diagnostic", read);
        return 0;
    }
    const popup::Result<popup::Scaffold> again =
        popup::scaffold_from_json(popup::scaffold_to_json(read.value));
    if (!again.ok)
        fail("a design that reads does not read back after scaffold_to_json", again);
    if (again.value.patches.size() != read.value.patches.size() ||
        again.value.hinges.size() != read.value.hinges.size())
        fail("the round trip changed the number of patches or hinges", again);
    return 0;
}
