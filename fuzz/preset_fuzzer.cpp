// libFuzzer target for the preset loader. Any input must either fail with well-formed errors or
// load; whatever loads must save and load back to exactly the same text.
// Build and run with `./lab fuzz [SECONDS]` (fuzz/run.sh).
#include "io/preset_io.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "preset_fuzzer: %s\n%s\n", what, detail.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const pl::LoadResult first = pl::parse_preset(text);
    if (first.ok() == !first.errors.empty()) fail("scene and errors disagree", first.error_text());
    if (!first.ok()) {
        for (const pl::PresetError& e : first.errors)
            if (e.message.empty() || e.message.find('\n') != std::string::npos || e.path.find('\n') != std::string::npos)
                fail("malformed error", e.path + ": " + e.message);
        return 0;
    }
    const std::string saved = pl::serialize_preset(*first.scene);
    const pl::LoadResult second = pl::parse_preset(saved);
    if (!second.ok()) fail("a loaded preset does not load back after saving", second.error_text() + "\n" + saved);
    const std::string saved_again = pl::serialize_preset(*second.scene);
    if (saved_again != saved) fail("saving is not stable", saved + "\n---\n" + saved_again);
    return 0;
}
