// A small XML reader (elements, attributes, text; no DTD, comments or entities other than
// the five predefined ones) so tests can read back the VTU files limber writes.
// Throws std::runtime_error on malformed or mismatched tags.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace limber::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  // character data directly inside the element
  std::vector<XmlElement> children;

  // The first child named `name`; throws when there is none.
  const XmlElement& child(const std::string& name) const;
  std::vector<const XmlElement*> children_named(const std::string& name) const;
  const std::string& attribute(const std::string& key) const;  // throws when absent
};

// The root element of `text` (an optional <?xml ...?> declaration first).
XmlElement parse_xml(const std::string& text);

// Decodes RFC 4648 base64 (whitespace ignored).
std::vector<unsigned char> base64_decode(const std::string& text);

}  // namespace limber::test
