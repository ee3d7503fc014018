// libFuzzer's entry point for one fuzz target, named at build time (RADIANT_FUZZ_TARGET, set by
// tests/fuzz/CMakeLists.txt for each fuzz_NAME harness).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include <OpenImageIO/imageio.h>

#include "fuzz_folder.h"
#include "fuzz_targets.h"

// OpenImageIO tries every reader it has (LibRaw, TIFF, DPX, ...) on a file its extension's reader
// refuses: their code, uninstrumented, at ~100 ms per input. Radiant's own code sees the same
// headers and pixels from the one reader, so the harnesses ask for that one only; the regression
// test replays findings with all of them.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  OIIO::attribute("try_all_readers", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const radiant::fuzz::FuzzFolder folder(RADIANT_FUZZ_TARGET);
  static const radiant::fuzz::FuzzTarget* target = radiant::fuzz::find_fuzz_target(RADIANT_FUZZ_TARGET);
  if (!target) {
    std::cerr << "no fuzz target named '" RADIANT_FUZZ_TARGET "'\n";
    std::abort();
  }
  target->run(folder.path, std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
