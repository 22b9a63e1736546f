// libFuzzer target for the case reader (docs/fuzzing.md): the bytes are a case file's text,
// fed through the whole input path of `limber run` up to the integration
// (case_input_path.h). InputError and NumericalError are expected ends; any other exception,
// an abort (LIMBER_DEMAND), a sanitizer report or a hang is a finding.
//
// Built only with -DLIMBER_FUZZ=ON and clang; run by scripts/fuzz-case-reader.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "case_input_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A folder that does not exist: a `base` key never reaches a real file.
  limber::fuzz::run_case_input(text, "/nonexistent-fuzz-input/case.yaml");
  return 0;
}
