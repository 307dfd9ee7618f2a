// XmlScanner: element tags and attributes of an XML text (see xml_scan.hpp).
#include "io/xml_scan.hpp"

#include <cstdint>

#include "core/error.hpp"

namespace partet {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
}

void append_utf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xc0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xe0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  }
}

// Decodes one entity starting after '&' in `s`; false if it is not one we know.
bool decode_entity(std::string_view s, size_t& i, std::string& out) {
  size_t semi = s.find(';', i);
  if (semi == std::string_view::npos || semi - i > 10) return false;
  std::string_view e = s.substr(i, semi - i);
  if (e == "amp")
    out += '&';
  else if (e == "lt")
    out += '<';
  else if (e == "gt")
    out += '>';
  else if (e == "quot")
    out += '"';
  else if (e == "apos")
    out += '\'';
  else if (e.size() >= 2 && e[0] == '#') {
    bool hex = e[1] == 'x' || e[1] == 'X';
    std::string_view digits = e.substr(hex ? 2 : 1);
    if (digits.empty()) return false;
    uint32_t cp = 0;
    for (char c : digits) {
      uint32_t d;
      if (c >= '0' && c <= '9')
        d = static_cast<uint32_t>(c - '0');
      else if (hex && c >= 'a' && c <= 'f')
        d = static_cast<uint32_t>(c - 'a' + 10);
      else if (hex && c >= 'A' && c <= 'F')
        d = static_cast<uint32_t>(c - 'A' + 10);
      else
        return false;
      cp = cp * (hex ? 16 : 10) + d;
      if (cp > 0x10ffff) return false;
    }
    if (cp == 0) return false;
    append_utf8(out, cp);
  } else {
    return false;
  }
  i = semi + 1;
  return true;
}

}  // namespace

void XmlScanner::fail(size_t offset, const std::string& message) const {
  throw InputError(file_ + ": byte " + std::to_string(offset) + ": " + message);
}

// Skips a comment, processing instruction, DOCTYPE or CDATA section starting at
// `at` (a '<'); returns the offset just past it.
size_t XmlScanner::skip_markup(size_t at) const {
  std::string_view rest = text_.substr(at);
  std::string_view close = ">";
  if (rest.starts_with("<!--"))
    close = "-->";
  else if (rest.starts_with("<![CDATA["))
    close = "]]>";
  else if (rest.starts_with("<?"))
    close = "?>";
  size_t end = text_.find(close, at + 2);
  if (end == std::string_view::npos) fail(at, "unterminated XML markup");
  return end + close.size();
}

bool XmlScanner::next(XmlTag& tag) {
  while (true) {
    size_t lt = text_.find('<', pos_);
    if (lt == std::string_view::npos) {
      pos_ = text_.size();
      return false;
    }
    if (lt + 1 < text_.size() && (text_[lt + 1] == '!' || text_[lt + 1] == '?')) {
      pos_ = skip_markup(lt);
      continue;
    }
    size_t p = lt + 1;
    tag.kind = XmlTag::kOpen;
    if (p < text_.size() && text_[p] == '/') {
      tag.kind = XmlTag::kClose;
      ++p;
    }
    size_t name_start = p;
    while (p < text_.size() && is_name_char(text_[p])) ++p;
    if (p == name_start) fail(lt, "'<' does not start an XML tag");
    tag.name = text_.substr(name_start, p - name_start);
    size_t attr_start = p;
    char quote = 0;
    for (; p < text_.size(); ++p) {
      char c = text_[p];
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>' || c == '<') {
        break;
      }
    }
    if (p >= text_.size() || text_[p] != '>')
      fail(lt, "unterminated tag <" + std::string(tag.name.substr(0, 40)) + ">");
    size_t attr_end = p;
    if (attr_end > attr_start && text_[attr_end - 1] == '/') {
      if (tag.kind == XmlTag::kClose) fail(lt, "malformed closing tag");
      tag.kind = XmlTag::kEmpty;
      --attr_end;
    }
    tag.attributes = text_.substr(attr_start, attr_end - attr_start);
    tag.begin = lt;
    tag.end = p + 1;
    pos_ = tag.end;
    return true;
  }
}

bool XmlScanner::attribute(const XmlTag& tag, std::string_view name, std::string& value) const {
  std::string_view a = tag.attributes;
  size_t base = static_cast<size_t>(a.data() - text_.data());
  size_t i = 0;
  while (true) {
    while (i < a.size() && is_space(a[i])) ++i;
    if (i >= a.size()) return false;
    size_t key_start = i;
    while (i < a.size() && is_name_char(a[i])) ++i;
    if (i == key_start) fail(base + i, "malformed attribute in <" + std::string(tag.name.substr(0, 40)) + ">");
    std::string_view key = a.substr(key_start, i - key_start);
    while (i < a.size() && is_space(a[i])) ++i;
    if (i >= a.size() || a[i] != '=') fail(base + i, "attribute '" + std::string(key.substr(0, 40)) + "' has no value");
    ++i;
    while (i < a.size() && is_space(a[i])) ++i;
    if (i >= a.size() || (a[i] != '"' && a[i] != '\''))
      fail(base + i, "value of attribute '" + std::string(key.substr(0, 40)) + "' is not quoted");
    char quote = a[i++];
    size_t close = a.find(quote, i);
    if (close == std::string_view::npos) fail(base + i, "unterminated attribute value");
    if (key == name) {
      value.clear();
      std::string_view raw = a.substr(i, close - i);
      for (size_t k = 0; k < raw.size();) {
        if (raw[k] == '&') {
          ++k;
          if (!decode_entity(raw, k, value)) fail(base + i + k - 1, "unknown XML entity");
        } else {
          value += raw[k++];
        }
      }
      return true;
    }
    i = close + 1;
  }
}

std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace partet
