#include "core/error.h"

#include <cstdio>
#include <cstdlib>

namespace limber {

std::string SourceLocation::to_string() const {
  if (!known()) return {};
  // Appended piecewise: `":" + std::to_string(n)` trips GCC 12's false -Wrestrict alarm.
  std::string text = file;
  if (line > 0) text.append(":").append(std::to_string(line));
  if (line > 0 && column > 0) text.append(":").append(std::to_string(column));
  return text;
}

namespace {
std::string located(const std::string& message, const SourceLocation& where) {
  return where.known() ? where.to_string() + ": " + message : message;
}
}  // namespace

InputError::InputError(const std::string& message, SourceLocation where)
    : std::runtime_error(located(message, where)), message_(message), where_(std::move(where)) {}

void demand_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "limber: internal error: %s failed at %s:%d\n", condition, file, line);
  std::abort();
}

}  // namespace limber
