#include "mini_xml.h"

#include <cctype>
#include <stdexcept>

namespace limber::test {

namespace {

class Parser {
 public:
  explicit Parser(const std::string& text) : text_(text) {}

  XmlElement parse_document() {
    skip_space();
    // Optional declaration.
    if (text_.compare(pos_, 5, "<?xml") == 0) {
      pos_ = text_.find("?>", pos_);
      if (pos_ == std::string::npos) fail("unterminated declaration");
      pos_ += 2;
    }
    skip_space();
    XmlElement root = parse_element();
    skip_space();
    if (pos_ != text_.size()) fail("text after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML: " + what + " at offset " + std::to_string(pos_));
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  std::string parse_name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
            text_[pos_] == '-' || text_[pos_] == ':' || text_[pos_] == '.')) {
      ++pos_;
    }
    if (pos_ == start) fail("expected a name");
    return text_.substr(start, pos_ - start);
  }
  static std::string unescape(const std::string& raw) {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      const std::size_t end = raw.find(';', i);
      const std::string entity = raw.substr(i + 1, end - i - 1);
      if (entity == "lt")
        out += '<';
      else if (entity == "gt")
        out += '>';
      else if (entity == "amp")
        out += '&';
      else if (entity == "quot")
        out += '"';
      else if (entity == "apos")
        out += '\'';
      else
        throw std::runtime_error("XML: unknown entity &" + entity + ";");
      i = end;
    }
    return out;
  }

  XmlElement parse_element() {
    if (text_[pos_] != '<') fail("expected '<'");
    ++pos_;
    XmlElement element;
    element.name = parse_name();
    // Attributes until '>' or '/>'.
    while (true) {
      skip_space();
      if (pos_ >= text_.size()) fail("unterminated tag");
      if (text_.compare(pos_, 2, "/>") == 0) {
        pos_ += 2;
        return element;
      }
      if (text_[pos_] == '>') {
        ++pos_;
        break;
      }
      const std::string key = parse_name();
      skip_space();
      if (text_[pos_] != '=') fail("expected '='");
      ++pos_;
      skip_space();
      const char quote = text_[pos_];
      if (quote != '"' && quote != '\'') fail("expected a quoted value");
      const std::size_t end = text_.find(quote, pos_ + 1);
      if (end == std::string::npos) fail("unterminated attribute");
      if (!element.attributes.emplace(key, unescape(text_.substr(pos_ + 1, end - pos_ - 1)))
               .second) {
        fail("duplicate attribute " + key);
      }
      pos_ = end + 1;
    }
    // Content: text and children until the matching end tag.
    while (true) {
      const std::size_t next = text_.find('<', pos_);
      if (next == std::string::npos) fail("missing </" + element.name + ">");
      element.text += unescape(text_.substr(pos_, next - pos_));
      pos_ = next;
      if (text_.compare(pos_, 2, "</") == 0) {
        pos_ += 2;
        if (parse_name() != element.name) fail("mismatched end tag for " + element.name);
        skip_space();
        if (text_[pos_] != '>') fail("expected '>'");
        ++pos_;
        return element;
      }
      element.children.push_back(parse_element());
    }
  }

  const std::string& text_;
  std::size_t pos_ = 0;
};

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

const XmlElement& XmlElement::child(const std::string& key) const {
  for (const XmlElement& c : children) {
    if (c.name == key) return c;
  }
  throw std::runtime_error("XML: <" + name + "> has no <" + key + ">");
}

std::vector<const XmlElement*> XmlElement::children_named(const std::string& key) const {
  std::vector<const XmlElement*> found;
  for (const XmlElement& c : children) {
    if (c.name == key) found.push_back(&c);
  }
  return found;
}

const std::string& XmlElement::attribute(const std::string& key) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) throw std::runtime_error("XML: <" + name + "> has no " + key);
  return it->second;
}

XmlElement parse_xml(const std::string& text) { return Parser(text).parse_document(); }

std::vector<unsigned char> base64_decode(const std::string& text) {
  std::vector<unsigned char> bytes;
  unsigned int buffer = 0;
  int bits = 0;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == '=') continue;
    const int value = base64_value(c);
    if (value < 0) throw std::runtime_error(std::string("base64: bad character ") + c);
    buffer = (buffer << 6) | static_cast<unsigned int>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return bytes;
}

}  // namespace limber::test
