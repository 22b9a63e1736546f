#include "core/input_file.h"

#include <system_error>

namespace limber {

std::string regular_file_problem(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) return "";
  if (!error) return "not a regular file";
  if (error == std::errc::no_such_file_or_directory) return "no such file";
  if (error == std::errc::filename_too_long) return "file name too long";
  return error.message();
}

std::string abbreviated(std::string_view text, std::size_t kept) {
  if (text.size() <= kept + 20) return std::string(text);
  // Cut before the character a UTF-8 continuation byte belongs to.
  std::size_t end = kept;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return std::string(text.substr(0, end)) + "… (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace limber
