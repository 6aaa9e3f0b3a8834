// libFuzzer target: the case loader and its validation. Contract: any text is
// either a Case or an InputError; nothing else escapes, nothing crashes. A case that
// loads must reload to the same case from its own resolved TOML (to_toml).
#include <cstdint>
#include <string>

#include "common/errors.hpp"
#include "io/case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const fsi::Case c = fsi::load_case_text(text, "fuzz.toml");
    const std::string resolved = fsi::to_toml(c);
    const fsi::Case again = fsi::load_case_text(resolved, "resolved.toml");
    if (fsi::to_toml(again) != resolved) __builtin_trap();  // the round trip must be exact
  } catch (const fsi::InputError&) {
  }
  return 0;
}
