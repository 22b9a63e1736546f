// Text shown as text in XML and HTML: & < > " ' escaped, so titles, names and messages from
// case and results files are safe in element content and in quoted attribute values alike
// (the report's HTML, the VTU series' PVD, the XDMF description).
#pragma once

#include <string>

namespace limber {

std::string markup_escape(const std::string& text);

}  // namespace limber
