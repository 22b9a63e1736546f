// Error channels of limber (house style §11):
//  - bad user input       -> throw InputError (message says expected/got, and where);
//  - broken invariant     -> LIMBER_DEMAND(cond) aborts with file:line;
//  - numerical failure    -> a returned status the caller handles (see each algorithm).
#pragma once

#include <stdexcept>
#include <string>

namespace limber {

// A place in a user's input file; line and column are 1-based, 0 when unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;

  bool known() const { return !file.empty(); }
  // "case.yaml:12:5" (or "" when unknown).
  std::string to_string() const;
};

// Bad user input. what() is "file:line:col: message" when the location is known.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, SourceLocation where = {});

  const std::string& message() const { return message_; }
  const SourceLocation& where() const { return where_; }

 private:
  std::string message_;
  SourceLocation where_;
};

// A numerical method failed on valid input where the command cannot go on and has no status to
// return (e.g. the eigen-solver of a flexible body a mechanism needs). Commands map it to their
// "numerical failure" exit code; the message says what failed and where.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void demand_failed(const char* condition, const char* file, int line);

}  // namespace limber

// Internal invariant: aborts with the condition and its place when false.
#define LIMBER_DEMAND(condition) \
  ((condition) ? static_cast<void>(0) : ::limber::demand_failed(#condition, __FILE__, __LINE__))
