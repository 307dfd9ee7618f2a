// libFuzzer target for parse_gmsh, as a volume read and as a surface read:
// any bytes give a well-formed mesh or an InputError; anything else is a
// finding (see fuzz_support.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "io/mesh_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (partet::MeshRead what : {partet::MeshRead::kVolume, partet::MeshRead::kSurface}) {
    partet::fuzz::expect_input_error_only("fuzz", [&] {
      partet::fuzz::check_volume(partet::parse_gmsh(partet::fuzz::as_bytes(data, size), "fuzz", what));
    });
  }
  return 0;
}
