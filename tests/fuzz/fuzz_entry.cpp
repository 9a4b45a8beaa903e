// The libFuzzer entry of one target; MICROSIM_FUZZ_TARGET names the function (set per
// executable by tests/fuzz/CMakeLists.txt).
#include "fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return microsim::fuzz::MICROSIM_FUZZ_TARGET(data, size);
}
