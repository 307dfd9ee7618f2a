// A small XML tag scanner for the VTK XML formats: it walks the element tags
// of a document in order (skipping text, comments, processing instructions,
// DOCTYPE and CDATA), and reads attributes on demand. It builds no tree and
// allocates nothing per tag; callers keep the nesting they care about.
// It does not validate the document beyond what it needs to find tags: a
// '<' that does not open a well-formed tag, an unterminated tag or comment,
// or a malformed attribute is an InputError naming "file: byte N".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace partet {

struct XmlTag {
  enum Kind { kOpen, kClose, kEmpty };  // <a ...>, </a>, <a .../>
  Kind kind = kOpen;
  std::string_view name;
  std::string_view attributes;  // raw text after the name, up to '>' or '/>'
  size_t begin = 0;             // offset of '<'
  size_t end = 0;               // offset just past '>'
};

class XmlScanner {
 public:
  XmlScanner(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  // Moves to the next element tag; false when the text holds no more tags.
  bool next(XmlTag& tag);

  // The value of attribute `name` of `tag`, with the five predefined entities
  // and numeric character references decoded; false if the tag has none.
  bool attribute(const XmlTag& tag, std::string_view name, std::string& value) const;

  std::string_view text() const { return text_; }
  const std::string& file() const { return file_; }

  // Throws InputError "file: byte N: message".
  [[noreturn]] void fail(size_t offset, const std::string& message) const;

 private:
  size_t skip_markup(size_t at) const;

  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
};

// Escapes &, <, >, " and ' for use in an attribute value.
std::string xml_escape(std::string_view s);

}  // namespace partet
