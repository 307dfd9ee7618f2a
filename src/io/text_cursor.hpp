// A cursor over the text of a file: whitespace-separated tokens and whole
// lines, with line tracking so that every error names "file:line".
// Numbers are parsed exactly (std::from_chars); nothing is allocated per token.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace partet {

class TextCursor {
 public:
  // `comment`: a character that starts a comment running to the end of the
  // line ('\0' for none).
  TextCursor(std::string_view text, std::string file, char comment = '\0');

  // Skips whitespace and comments; true when a token follows.
  bool has_token();
  // The next token; fails with "unexpected end of file, expected <what>".
  std::string_view token(const char* what);
  // The next token parsed as a number; fails naming `what` when it is not one.
  // Accepts a leading '+', and nan/inf (the surface diagnosis reports those).
  double real(const char* what);
  int64_t integer(const char* what);
  // A non-negative count no larger than `limit` (guards against headers that
  // claim more data than a file can hold).
  uint64_t count(const char* what, uint64_t limit);

  // The rest of the current line (without comment and line break), then moves
  // to the next line. False at the end of the text.
  bool line(std::string_view& out);

  // 1-based line of the most recent token or line.
  size_t line_number() const { return token_line_; }
  size_t offset() const { return pos_; }
  size_t size() const { return text_.size(); }
  const std::string& file() const { return file_; }
  std::string_view text() const { return text_; }
  // Moves to byte offset `pos` (used where a text header is followed by binary data).
  void seek(size_t pos);

  // Throws InputError "file:line: message".
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void skip_space();

  std::string_view text_;
  std::string file_;
  char comment_;
  size_t pos_ = 0;
  size_t line_ = 1;        // line of pos_
  size_t token_line_ = 1;  // line of the last token returned
};

// Splits `s` on whitespace into at most `max` views; returns how many.
size_t split_tokens(std::string_view s, std::string_view* out, size_t max);

// Parses all of `s` as a double (leading '+', nan, inf allowed); false if it is not one.
bool parse_real(std::string_view s, double& out);
// Parses all of `s` as a signed 64-bit integer; false if it is not one.
bool parse_integer(std::string_view s, int64_t& out);

}  // namespace partet
