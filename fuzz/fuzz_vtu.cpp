// libFuzzer target for parse_vtu and parse_pvtu_pieces: any bytes give a
// well-formed mesh (or piece list) or an InputError; anything else is a
// finding (see fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "io/mesh_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  partet::fuzz::expect_input_error_only("fuzz.vtu", [&] {
    partet::fuzz::check_volume(partet::parse_vtu(partet::fuzz::as_bytes(data, size), "fuzz.vtu"));
  });
  partet::fuzz::expect_input_error_only("fuzz.pvtu", [&] {
    partet::parse_pvtu_pieces(partet::fuzz::as_bytes(data, size), "fuzz.pvtu");
  });
  return 0;
}
