// libFuzzer target for parse_off: any bytes give a well-formed surface or an
// InputError; anything else is a finding (see fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "io/surface_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  partet::fuzz::expect_input_error_only("fuzz.off", [&] {
    partet::fuzz::check_surface(partet::parse_off(partet::fuzz::as_bytes(data, size), "fuzz.off"));
  });
  return 0;
}
