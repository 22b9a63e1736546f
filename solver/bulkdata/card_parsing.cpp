#include "bulkdata/card_parsing.h"

#include <set>

namespace limber::bulkdata {

// Fails unless the field is blank or the real zero.
void demand_zero(const CardFields& f, int field, const char* name, const char* what) {
  if (f.blank(field)) return;
  const std::optional<int> as_integer = parse_integer(f.text(field));
  const double value = as_integer ? *as_integer : f.real(field, name);
  if (value != 0.0) {
    f.fail(field, name, fmt::format("expected blank or 0.0 ({} not supported), got '{}'", what,
                                    f.text(field)));
  }
}

double positive(const CardFields& f, int field, const char* name) {
  const double value = f.real(field, name);
  if (!(value > 0.0)) f.fail(field, name, fmt::format("expected a value > 0, got {}", value));
  return value;
}

// DOF component digits 1-6, each at most once ("" when blank).
std::string components(const CardFields& f, int field, const char* name) {
  const std::string& text = f.text(field);
  std::set<char> seen;
  for (char c : text) {
    if (c < '1' || c > '6' || !seen.insert(c).second) {
      f.fail(field, name,
             fmt::format("expected component digits 1-6, each once (e.g. 123456), got '{}'", text));
    }
  }
  return text;
}

// Ids from `first` to the card's last field, with "A THRU B" ranges; blanks are skipped.
std::vector<IdRange> id_list(const CardFields& f, int first, const char* name) {
  std::vector<IdRange> ids;
  const int last = f.last_field();
  const auto skipped = [&](int field) { return field % 10 == 0 || field % 10 == 1 || f.blank(field); };
  for (int field = first; field <= last; ++field) {
    if (skipped(field)) continue;  // continuation markers, blanks
    if (f.text(field) == "THRU") {
      int next = field + 1;
      while (next <= last && skipped(next)) ++next;
      if (ids.empty() || ids.back().first != ids.back().last || next > last) {
        f.fail(field, name, "expected 'id THRU id', got THRU without an id on both sides");
      }
      const int to = f.id(next, name);
      if (to < ids.back().first) {
        f.fail(next, name, fmt::format("expected an end id >= {}, got {}", ids.back().first, to));
      }
      ids.back().last = to;
      field = next;
      continue;
    }
    const int id = f.id(field, name);
    ids.push_back({id, id});
  }
  if (ids.empty()) f.fail(first, name, "expected at least one id, got none");
  return ids;
}

std::vector<int> data_fields(const CardFields& f, int first) {
  std::vector<int> fields;
  for (int field = first; field <= f.last_field(); ++field) {
    if (field % 10 == 0 || field % 10 == 1) continue;
    fields.push_back(field);
  }
  return fields;
}

void rod_section(const CardFields& f, int first, double& area, double& torsion, double& nsm) {
  area = positive(f, first, "A");
  torsion = f.real_or(first + 1, "J", 0.0);
  if (torsion < 0.0) f.fail(first + 1, "J", "expected a torsion constant >= 0");
  nsm = f.real_or(first + 3, "NSM", 0.0);
  if (!(nsm >= 0.0)) f.fail(first + 3, "NSM", "expected a value >= 0");
}

}  // namespace limber::bulkdata
