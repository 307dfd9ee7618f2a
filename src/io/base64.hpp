// Base64 (RFC 4648, standard alphabet, '=' padding) for VTK XML data arrays.
// The encoder streams: bytes written in several calls come out as one
// base64 stream. The decoder reads a byte count on demand from a position in
// a text, skips whitespace, and accepts concatenated padded streams (a
// header encoded apart from its data, as meshio writes) as well as a single
// stream (as VTK writes): a padded group just yields fewer bytes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace partet {

class Base64Encoder {
 public:
  explicit Base64Encoder(std::string& out) : out_(out) {}
  void write(const void* data, size_t n);
  // Writes the last partial group with its padding; call once at the end.
  void finish();

 private:
  void emit(unsigned a, unsigned b, unsigned c, size_t valid);

  std::string& out_;
  unsigned char pending_[3] = {0, 0, 0};
  size_t num_pending_ = 0;
};

class Base64Decoder {
 public:
  Base64Decoder(std::string_view text, size_t pos) : text_(text), pos_(pos) {}
  // Decodes the next `n` bytes into `out`. False when the text ends first or
  // holds a character that is not base64 (position() then points at it).
  bool read(size_t n, char* out);
  // Offset in the text of the next character not yet decoded.
  size_t position() const { return pos_; }
  // An upper bound on the bytes that read() could still produce.
  size_t max_bytes() const { return (text_.size() - pos_) / 4 * 3 + (num_buffered_ - buffer_pos_); }

 private:
  bool next_group();

  std::string_view text_;
  size_t pos_;
  char buffer_[3] = {0, 0, 0};
  size_t num_buffered_ = 0;
  size_t buffer_pos_ = 0;
};

}  // namespace partet
