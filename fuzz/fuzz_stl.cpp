// libFuzzer target for parse_stl: any bytes give a well-formed surface or an
// InputError; anything else is a finding (see fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "io/surface_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  partet::fuzz::expect_input_error_only("fuzz.stl", [&] {
    partet::fuzz::check_surface(partet::parse_stl(partet::fuzz::as_bytes(data, size), "fuzz.stl"));
  });
  return 0;
}
