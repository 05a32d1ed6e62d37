// libFuzzer target for the input path of the tools (see fuzz_input_path.h):
// bytes -> mesh file -> read, validate, repair -> small unwrap -> invariants.
// Built by fuzz/CMakeLists.txt with clang and -fsanitize=fuzzer,address,undefined
// when CUT_PARAM_BUILD_FUZZER is ON; run with scripts/run_fuzzer.sh.
#include "fuzz_input_path.h"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

std::string scratch_directory()
{
  const char* dir = std::getenv("TMPDIR");
  return (dir && *dir) ? dir : "/tmp";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::string scratch = scratch_directory();
  fuzz_input::run(data, size, scratch);
  return 0;
}
