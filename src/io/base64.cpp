// Base64 encoding and decoding (see base64.hpp).
#include "io/base64.hpp"

#include <cstring>

namespace partet {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Value of each character: 0-63 for the alphabet, 64 for '=', -1 for
// whitespace, -2 for anything else.
struct DecodeTable {
  signed char value[256];
  constexpr DecodeTable() : value() {
    for (int c = 0; c < 256; ++c) value[c] = -2;
    for (int i = 0; i < 64; ++i) value[static_cast<unsigned char>(kAlphabet[i])] = static_cast<signed char>(i);
    value[static_cast<unsigned char>('=')] = 64;
    for (char c : {' ', '\n', '\r', '\t'}) value[static_cast<unsigned char>(c)] = -1;
  }
};
constexpr DecodeTable kDecode;

int char_value(char c) { return kDecode.value[static_cast<unsigned char>(c)]; }

}  // namespace

void Base64Encoder::emit(unsigned a, unsigned b, unsigned c, size_t valid) {
  unsigned v = (a << 16) | (b << 8) | c;
  char group[4] = {kAlphabet[(v >> 18) & 63], kAlphabet[(v >> 12) & 63], kAlphabet[(v >> 6) & 63], kAlphabet[v & 63]};
  if (valid < 3) group[3] = '=';
  if (valid < 2) group[2] = '=';
  out_.append(group, 4);
}

void Base64Encoder::write(const void* data, size_t n) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  out_.reserve(out_.size() + (n + 2) / 3 * 4);
  while (n > 0 && num_pending_ > 0 && num_pending_ < 3) {
    pending_[num_pending_++] = *p++;
    --n;
  }
  if (num_pending_ == 3) {
    emit(pending_[0], pending_[1], pending_[2], 3);
    num_pending_ = 0;
  }
  for (; n >= 3; n -= 3, p += 3) emit(p[0], p[1], p[2], 3);
  for (; n > 0; --n) pending_[num_pending_++] = *p++;
}

void Base64Encoder::finish() {
  if (num_pending_ == 0) return;
  emit(pending_[0], num_pending_ > 1 ? pending_[1] : 0u, 0u, num_pending_);
  num_pending_ = 0;
}

bool Base64Decoder::next_group() {
  int v[4];
  size_t got = 0;
  size_t p = pos_;
  while (got < 4) {
    if (p >= text_.size()) return false;
    int c = char_value(text_[p]);
    if (c == -2) {
      pos_ = p;
      return false;
    }
    ++p;
    if (c == -1) continue;
    if (c == 64 && got < 2) {
      pos_ = p - 1;
      return false;
    }
    v[got++] = c;
  }
  if (v[2] == 64 && v[3] != 64) return false;
  unsigned bits = (static_cast<unsigned>(v[0]) << 18) | (static_cast<unsigned>(v[1]) << 12) |
                  (static_cast<unsigned>(v[2] & 63) << 6) | static_cast<unsigned>(v[3] & 63);
  buffer_[0] = static_cast<char>((bits >> 16) & 0xff);
  buffer_[1] = static_cast<char>((bits >> 8) & 0xff);
  buffer_[2] = static_cast<char>(bits & 0xff);
  num_buffered_ = v[2] == 64 ? 1 : v[3] == 64 ? 2 : 3;
  buffer_pos_ = 0;
  pos_ = p;
  return true;
}

bool Base64Decoder::read(size_t n, char* out) {
  while (n > 0) {
    if (buffer_pos_ < num_buffered_) {
      size_t k = num_buffered_ - buffer_pos_;
      if (k > n) k = n;
      std::memcpy(out, buffer_ + buffer_pos_, k);
      buffer_pos_ += k;
      out += k;
      n -= k;
      continue;
    }
    // Fast path: whole groups of alphabet characters straight to the output.
    while (n >= 3 && text_.size() - pos_ >= 4) {
      const char* p = text_.data() + pos_;
      int a = char_value(p[0]), b = char_value(p[1]), c = char_value(p[2]), d = char_value(p[3]);
      if (((a | b | c | d) & ~63) != 0) break;
      unsigned bits = (static_cast<unsigned>(a) << 18) | (static_cast<unsigned>(b) << 12) |
                      (static_cast<unsigned>(c) << 6) | static_cast<unsigned>(d);
      out[0] = static_cast<char>((bits >> 16) & 0xff);
      out[1] = static_cast<char>((bits >> 8) & 0xff);
      out[2] = static_cast<char>(bits & 0xff);
      out += 3;
      n -= 3;
      pos_ += 4;
    }
    if (n > 0 && !next_group()) return false;
  }
  return true;
}

}  // namespace partet
