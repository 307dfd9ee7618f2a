// TextCursor: tokens and lines of a text file with "file:line" errors.
#include "io/text_cursor.hpp"

#include <charconv>

#include "core/error.hpp"

namespace partet {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The power of ten of the leading nonzero digit of a decimal number that
// from_chars found out of range (so nonzero and finite): positive when it
// overflows, negative when it underflows, whatever mantissa and exponent say
// separately ("1000...0e-5" overflows, "0.000...01e5" underflows).
int64_t decimal_order(std::string_view s) {
  size_t i = s.front() == '-' ? 1 : 0;
  int64_t order = 0;
  bool found = false;
  for (; i < s.size() && is_digit(s[i]); ++i) {
    if (found) ++order;
    found = found || s[i] != '0';
  }
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && is_digit(s[i]); ++i) {
      if (!found) --order;
      found = found || s[i] != '0';
    }
  }
  int64_t exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    bool negative = ++i < s.size() && s[i] == '-';
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    for (; i < s.size() && is_digit(s[i]) && exponent < 1000000000; ++i) exponent = 10 * exponent + (s[i] - '0');
    if (negative) exponent = -exponent;
  }
  return order + exponent;
}
}  // namespace

TextCursor::TextCursor(std::string_view text, std::string file, char comment)
    : text_(text), file_(std::move(file)), comment_(comment) {}

void TextCursor::skip_space() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

bool TextCursor::has_token() {
  skip_space();
  return pos_ < text_.size();
}

std::string_view TextCursor::token(const char* what) {
  skip_space();
  token_line_ = line_;
  if (pos_ >= text_.size()) fail(std::string("unexpected end of file, expected ") + what);
  size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) &&
         !(comment_ != '\0' && text_[pos_] == comment_))
    ++pos_;
  return text_.substr(start, pos_ - start);
}

double TextCursor::real(const char* what) {
  std::string_view t = token(what);
  double v = 0;
  if (!parse_real(t, v)) fail(std::string("expected ") + what + ", found '" + std::string(t.substr(0, 40)) + "'");
  return v;
}

int64_t TextCursor::integer(const char* what) {
  std::string_view t = token(what);
  int64_t v = 0;
  if (!parse_integer(t, v)) fail(std::string("expected ") + what + " (an integer), found '" + std::string(t.substr(0, 40)) + "'");
  return v;
}

uint64_t TextCursor::count(const char* what, uint64_t limit) {
  int64_t v = integer(what);
  if (v < 0) fail(std::string(what) + " is negative (" + std::to_string(v) + ")");
  if (static_cast<uint64_t>(v) > limit)
    fail(std::string(what) + " " + std::to_string(v) + " is more than the file can hold");
  return static_cast<uint64_t>(v);
}

bool TextCursor::line(std::string_view& out) {
  if (pos_ >= text_.size()) return false;
  token_line_ = line_;
  size_t start = pos_;
  size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  pos_ = end < text_.size() ? end + 1 : end;
  if (end < text_.size()) ++line_;
  std::string_view l = text_.substr(start, end - start);
  if (comment_ != '\0') {
    size_t c = l.find(comment_);
    if (c != std::string_view::npos) l = l.substr(0, c);
  }
  while (!l.empty() && is_space(l.back())) l.remove_suffix(1);
  out = l;
  return true;
}

void TextCursor::seek(size_t pos) {
  for (size_t i = pos_; i < pos && i < text_.size(); ++i)
    if (text_[i] == '\n') ++line_;
  pos_ = pos;
}

void TextCursor::fail(const std::string& message) const {
  throw InputError(file_ + ":" + std::to_string(token_line_) + ": " + message);
}

size_t split_tokens(std::string_view s, std::string_view* out, size_t max) {
  size_t n = 0, i = 0;
  while (i < s.size() && n < max) {
    while (i < s.size() && is_space(s[i])) ++i;
    if (i >= s.size()) break;
    size_t start = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    out[n++] = s.substr(start, i - start);
  }
  return n;
}

bool parse_real(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-') return false;
  }
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  if (ec == std::errc::result_out_of_range) {
    // Overflow reads as infinity, underflow as zero: the value is still a number.
    bool neg = s.front() == '-';
    out = decimal_order(s) > 0 ? (neg ? -__builtin_inf() : __builtin_inf()) : (neg ? -0.0 : 0.0);
    return ptr == s.data() + s.size();
  }
  return ec == std::errc() && ptr == s.data() + s.size();
}

bool parse_integer(std::string_view s, int64_t& out) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && s.front() == '-') return false;
  }
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

}  // namespace partet
