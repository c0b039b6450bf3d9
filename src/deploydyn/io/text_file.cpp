#include "deploydyn/io/text_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "deploydyn/io/input_error.hpp"

namespace deploydyn::io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem) {
  throw InputError(file.string(), 0, 0, "", problem);
}

// Length of the UTF-8 sequence at text[i] (1–4), or 0 when the bytes there are not UTF-8.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t n = 0;
  char32_t code = 0;
  if (lead < 0x80) return 1;
  if ((lead & 0xE0) == 0xC0) n = 2, code = lead & 0x1F;
  else if ((lead & 0xF0) == 0xE0) n = 3, code = lead & 0x0F;
  else if ((lead & 0xF8) == 0xF0) n = 4, code = lead & 0x07;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  // Overlong forms, surrogates and code points beyond Unicode are not UTF-8.
  constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[n] || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF) return 0;
  return n;
}

}  // namespace

std::string read_input_file(const std::filesystem::path& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (error || !std::filesystem::exists(status)) {
    fail(file, fmt::format("cannot open file: {}", error ? error.message() : std::strerror(ENOENT)));
  }
  if (std::filesystem::is_directory(status)) fail(file, "is a folder; give a model or study file");
  if (!std::filesystem::is_regular_file(status)) {
    fail(file, "is not a regular file (a device, pipe or socket); give a model or study file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > kMaxInputFileBytes) {
    fail(file, fmt::format("is {} MiB; input files may have at most {} MiB", size >> 20,
                           kMaxInputFileBytes >> 20));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, fmt::format("cannot open file: {}", std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(file, fmt::format("cannot read file: {}", std::strerror(errno)));
  std::string content = std::move(text).str();
  if (content.find('\0') != std::string::npos) {
    fail(file, "is not a text file (it holds NUL bytes: binary, or UTF-16 text); model and "
               "study files are UTF-8 text");
  }
  return content;
}

bool is_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::size_t end = 0;
  for (std::size_t n_chars = 0; end < text.size() && n_chars < max_chars; ++n_chars) {
    end += std::max<std::size_t>(utf8_length(text, end), 1);  // a stray byte counts as one
  }
  if (end >= text.size()) return std::string(text);
  return std::string(text.substr(0, end)) + "…";
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    const auto lead = static_cast<unsigned char>(text[i]);
    // C1 controls U+0080–U+009F are C2 80 … C2 9F in UTF-8 (0x9B alone is a terminal's CSI).
    const bool c1 = n == 2 && lead == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    if (n == 1 && lead >= 0x20 && lead != 0x7F) {
      out += text[i];
    } else if (n == 1 && lead == '\n') {
      out += "\\n";
    } else if (n == 1 && lead == '\t') {
      out += "\\t";
    } else if (n > 1 && !c1) {
      out.append(text.substr(i, n));
    } else {
      for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k) {
        out += fmt::format("\\x{:02X}", static_cast<unsigned char>(text[i + k]));
      }
    }
    i += std::max<std::size_t>(n, 1);
  }
  return out;
}

std::string name_problem(std::string_view name) {
  if (name.empty()) return "a name must not be empty";
  if (name.size() > kMaxFileNameBytes) {
    return fmt::format("a name must be at most {} bytes (it may name a folder), got {} bytes", kMaxFileNameBytes,
                       name.size());
  }
  for (std::size_t i = 0; i < name.size();) {
    const std::size_t n = utf8_length(name, i);
    const auto lead = static_cast<unsigned char>(name[i]);
    if (n == 0) return "a name must be UTF-8 text";
    if ((n == 1 && (lead < 0x20 || lead == 0x7F)) ||
        (n == 2 && lead == 0xC2 && static_cast<unsigned char>(name[i + 1]) < 0xA0)) {
      return "a name must not hold control characters";
    }
    if (lead == ',' || lead == '"') {
      return "a name must not hold commas or double quotes (it heads a CSV column)";
    }
    i += n;
  }
  return {};
}

}  // namespace deploydyn::io
