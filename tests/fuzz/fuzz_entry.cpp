// libFuzzer's entry point for one harness, chosen at compile time with
// -DINKRAY_FUZZ_TARGET=fuzz_scene_reader (see tests/fuzz/CMakeLists.txt).
#include "tests/fuzz/fuzz_targets.h"

#include <cstdio>
#include <cstdlib>

namespace inkray {

void fuzz_fail(const std::string& what) {
  std::fprintf(stderr, "fuzz oracle failed: %s\n", what.c_str());
  std::abort();
}

}  // namespace inkray

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return inkray::INKRAY_FUZZ_TARGET(data, size);
}
