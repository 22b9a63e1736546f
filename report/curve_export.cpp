#include "curve_export.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <cmath>
#include <vector>

namespace limber::report {
namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// "[N]" from "force [N]"; "" when there is no bracketed unit.
std::string unit_of(const std::string& label) {
  const std::size_t open = label.rfind('[');
  const std::size_t close = label.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return "";
  return label.substr(open, close - open + 1);
}

// Shortest text that reads back to the same double (fmt's default for "{}").
std::string exact(double value) { return fmt::format("{}", value); }

std::string json_number(double value) { return std::isfinite(value) ? exact(value) : "null"; }

}  // namespace

std::string curve_csv(const CurveTable& table, const std::string& x_label,
                      const std::string& y_label, const std::string& comment) {
  const std::string unit = unit_of(y_label);
  std::string out = comment.empty() ? "" : "# " + comment + "\n";
  out += csv_field(x_label);
  for (const std::string& label : table.labels) {
    out += ',';
    out += csv_field(unit.empty() ? label : label + " " + unit);
  }
  out += "\n";
  for (std::size_t r = 0; r < table.x.size(); ++r) {
    out += exact(table.x[r]);
    for (const std::vector<double>& column : table.columns) {
      out += ',';
      if (!std::isnan(column[r])) out += exact(column[r]);
    }
    out += '\n';
  }
  return out;
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '<': out += "\\u003c"; break;
      case '>': out += "\\u003e"; break;
      case '&': out += "\\u0026"; break;
      default:
        if (u < 0x20 || u == 0x7f) {
          out += fmt::format("\\u{:04x}", u);
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string curve_json(const PlotSpec& plot, const CurveTable& table, const std::string& full) {
  // A logarithmic axis only when every value is positive, as the PNG (plot.h).
  bool log = plot.log_y;
  for (const std::vector<double>& column : table.columns) {
    for (double v : column) log = log && (std::isnan(v) || v > 0.0);
  }
  std::string out = fmt::format(
      "{{\"title\":{},\"xlabel\":{},\"ylabel\":{},\"log\":{},\"samples\":{},\"labels\":[{}",
      json_string(plot.title), json_string(plot.x_label), json_string(plot.y_label),
      log ? "true" : "false", table.samples, json_string(plot.x_label));
  // dygraphs needs distinct labels: a repeated one gets " (2)", " (3)"...
  std::vector<std::string> seen{plot.x_label};
  for (const std::string& label : table.labels) {
    std::string unique = label;
    for (int k = 2; std::find(seen.begin(), seen.end(), unique) != seen.end(); ++k) {
      unique = label + " (" + std::to_string(k) + ")";
    }
    seen.push_back(unique);
    out += ',';
    out += json_string(unique);
  }
  out += "],\"colors\":[";
  for (std::size_t i = 0; i < table.labels.size(); ++i) {
    const auto& rgb = i < plot.curves.size() ? curve_color(plot.curves[i], i) : kCurveColors[i % kCurveColors.size()];
    out += fmt::format("{}\"#{:02x}{:02x}{:02x}\"", i > 0 ? "," : "", rgb[0], rgb[1], rgb[2]);
  }
  // Each curve's dash pattern in pixels (dygraphs' strokePattern; null: solid), as the PNG.
  out += "],\"dashes\":[";
  for (std::size_t i = 0; i < table.labels.size(); ++i) {
    const LineStyle style = i < plot.curves.size() ? plot.curves[i].style : LineStyle::kSolid;
    out += i > 0 ? "," : "";
    out += style == LineStyle::kDashed    ? "[10,6]"
           : style == LineStyle::kDotted  ? "[2,4]"
           : style == LineStyle::kDashDot ? "[10,4,2,4]"
                                          : "null";
  }
  // Each curve's line width [pixels] (the PNG's extra width over dygraphs' 1.5).
  out += "],\"widths\":[";
  for (std::size_t i = 0; i < table.labels.size(); ++i) {
    const float extra = i < plot.curves.size() ? plot.curves[i].extra_width : 0.0f;
    out += fmt::format("{}{:g}", i > 0 ? "," : "", 1.5 + extra);
  }
  out += "],\"data\":[";
  for (std::size_t r = 0; r < table.x.size(); ++r) {
    out += r > 0 ? ",[" : "[";
    out += json_number(table.x[r]);
    for (const std::vector<double>& column : table.columns) {
      out += ',';
      out += json_number(column[r]);
    }
    out += ']';
  }
  out += ']';
  if (!full.empty()) out += ",\"full\":" + full;
  return out + "}";
}

std::string base64_doubles(const Eigen::Ref<const Eigen::VectorXd>& values) {
  static_assert(std::endian::native == std::endian::little, "base64_doubles writes the native bytes");
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes(static_cast<std::size_t>(values.size()) * sizeof(double));
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    const double v = values(k);
    std::memcpy(bytes.data() + static_cast<std::size_t>(k) * sizeof(double), &v, sizeof(double));
  }
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  // Three bytes become four characters; the tail is padded with '='.
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const unsigned word = (unsigned{bytes[i]} << 16) | (left > 1 ? unsigned{bytes[i + 1]} << 8 : 0u) |
                          (left > 2 ? unsigned{bytes[i + 2]} : 0u);
    out += kAlphabet[(word >> 18) & 63];
    out += kAlphabet[(word >> 12) & 63];
    out += left > 1 ? kAlphabet[(word >> 6) & 63] : '=';
    out += left > 2 ? kAlphabet[word & 63] : '=';
  }
  return out;
}

std::string full_resolution_json(const std::vector<Curve>& curves, int columns) {
  bool shared = !curves.empty();
  for (const Curve& c : curves) shared = shared && c.x.size() == curves.front().x.size() && c.x == curves.front().x;
  std::string out = fmt::format("{{\"columns\":{},\"x\":", columns);
  out += shared ? "\"" + base64_doubles(curves.front().x) + "\"" : std::string("null");
  out += ",\"curves\":[";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const Curve& c = curves[i];
    const Eigen::Index n = std::min(c.x.size(), c.y.size());
    out += i > 0 ? ",{" : "{";
    if (!shared) out += "\"x\":\"" + base64_doubles(c.x.head(n)) + "\",";
    out += "\"y\":\"" + base64_doubles(c.y.head(n)) + "\"}";
  }
  return out + "]}";
}

}  // namespace limber::report
