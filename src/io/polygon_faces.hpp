// Faces that are not triangles, met while reading a surface: all are
// counted, the first few are named, and one InputError refuses them together.
#pragma once

#include <cstdint>
#include <string>

#include "core/error.hpp"

namespace partet {

class PolygonFaces {
 public:
  // `located`: "file:line" or "file: byte N" of the face; `where`: "line N" or "byte N".
  void add(uint64_t face, uint64_t vertices, const std::string& located, const std::string& where) {
    if (count_ == 0) {
      first_ = located + ": face " + std::to_string(face) + " has " + std::to_string(vertices) + " vertices";
    } else if (count_ <= 3) {
      others_ += ", face " + std::to_string(face) + " at " + where + " (" + std::to_string(vertices) + " vertices)";
    }
    ++count_;
  }

  void check() const {
    if (count_ == 0) return;
    throw InputError(first_ + "; partet meshes triangle surfaces only (" + std::to_string(count_) +
                     " faces are not triangles" + (others_.empty() ? "" : "; also" + others_.substr(1)) +
                     (count_ > 4 ? ", ..." : "") + ")");
  }

 private:
  uint64_t count_ = 0;
  std::string first_;
  std::string others_;
};

}  // namespace partet
