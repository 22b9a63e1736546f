// The reader of the run record (run_record.h): the members of an object at its own level, each
// value skipped whole (nested objects, arrays and strings), so a key is only ever read where
// the writer put it.
#include <cstdlib>
#include <map>

#include "core/error.h"
#include "core/json_text.h"
#include "run/run_record.h"

namespace limber::run {

namespace {

void skip_space(const std::string& text, std::size_t& at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\n' || text[at] == '\t' || text[at] == '\r')) ++at;
}

// Moves `at` past the value that starts there: a string, an object or array (to its matching
// close), or a number or literal (to the next ',', '}' or ']').
void skip_value(const std::string& text, std::size_t& at) {
  if (at < text.size() && text[at] == '"') {
    json_read_string(text, at);
    return;
  }
  int depth = 0;
  while (at < text.size()) {
    const char c = text[at];
    if (c == '"') {
      json_read_string(text, at);
      continue;
    }
    if (c == '{' || c == '[') ++depth;
    if (c == '}' || c == ']' || c == ',') {
      if (depth == 0) return;
      if (c != ',') --depth;
      if (depth == 0 && c != ',') {
        ++at;
        return;
      }
    }
    ++at;
  }
}

// The members of the object `text`: key -> the value's text as written.
std::map<std::string, std::string> members(const std::string& text) {
  std::map<std::string, std::string> found;
  std::size_t at = 0;
  skip_space(text, at);
  if (at >= text.size() || text[at] != '{') throw InputError("run record: expected a JSON object, got '" + text.substr(0, 40) + "'");
  ++at;
  for (;;) {
    skip_space(text, at);
    if (at >= text.size() || text[at] == '}') return found;
    if (text[at] != '"') throw InputError("run record: expected a member name at offset " + std::to_string(at));
    const std::string key = json_read_string(text, at);
    skip_space(text, at);
    if (at >= text.size() || text[at] != ':') throw InputError("run record: expected ':' after \"" + key + "\"");
    ++at;
    skip_space(text, at);
    const std::size_t start = at;
    skip_value(text, at);
    found[key] = text.substr(start, at - start);
    skip_space(text, at);
    if (at < text.size() && text[at] == ',') ++at;
  }
}

double number(const std::map<std::string, std::string>& object, const std::string& key) {
  const auto it = object.find(key);
  if (it == object.end()) return RunRecord::kAbsent;
  char* end = nullptr;
  const double value = std::strtod(it->second.c_str(), &end);
  return end == it->second.c_str() ? RunRecord::kAbsent : value;  // null
}

long count(const std::map<std::string, std::string>& object, const std::string& key) {
  const double value = number(object, key);
  return value == value ? static_cast<long>(value) : 0;
}

std::string text(const std::map<std::string, std::string>& object, const std::string& key) {
  const auto it = object.find(key);
  if (it == object.end() || it->second.empty() || it->second.front() != '"') return "";
  std::size_t at = 0;
  return json_read_string(it->second, at);
}

}  // namespace

RunRecord read_run_record(const std::string& document) {
  const std::map<std::string, std::string> top = members(document);
  RunRecord record;
  record.status = text(top, "status");
  record.message = text(top, "message");
  record.integrator = text(top, "integrator");
  record.t_end = number(top, "t_end");
  record.t_reached = number(top, "t_reached");
  record.samples = count(top, "samples");
  record.steps = count(top, "steps");
  record.rejected_steps = count(top, "rejected_steps");
  record.newton_failures = count(top, "newton_failures");
  record.newton_iterations = count(top, "newton_iterations");
  record.jacobian_evaluations = count(top, "jacobian_evaluations");
  record.residual_evaluations = count(top, "residual_evaluations");
  record.wall_s = number(top, "wall_s");
  record.max_constraint_violation = number(top, "max_constraint_violation");
  record.max_velocity_violation = number(top, "max_velocity_violation");
  record.results = text(top, "results");
  const auto accuracy = top.find("accuracy");
  if (accuracy != top.end() && !accuracy->second.empty() && accuracy->second.front() == '{') {
    const std::map<std::string, std::string> nested = members(accuracy->second);
    record.energy_relative = number(nested, "energy_relative");
    record.local_error = number(nested, "local_error");
    record.drift_relative = number(nested, "drift_relative");
  }
  return record;
}

}  // namespace limber::run
