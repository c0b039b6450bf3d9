#pragma once
// Reading a model or study file, showing user text safely in messages, and the names that
// user text may give to things.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace deploydyn::io {

// The largest input file read (bytes). A 10⁵-bar generated roof is about 15 MB, and the YAML
// parser needs about 70 bytes of memory per byte of file.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{256} << 20;

// The whole text of `file`. Throws InputError, before reading, for a file that is missing,
// not a regular file (a folder, a device such as /dev/zero, a pipe) or larger than
// kMaxInputFileBytes, and after reading for one that is not text (NUL bytes: binary or
// UTF-16); the message gives the operating system's reason where there is one.
std::string read_input_file(const std::filesystem::path& file);

// Whether `text` is UTF-8: no stray or missing continuation bytes, overlong forms, surrogates
// or code points beyond Unicode.
bool is_utf8(std::string_view text);

// The characters of user text a message quotes at most: a binary file or a pasted table must
// not fill the terminal.
inline constexpr std::size_t kMaxExcerptChars = 60;

// `text` as a message quotes it: whole when short, else its first `max_chars` characters
// (whole UTF-8 sequences) and "…".
std::string excerpt(std::string_view text, std::size_t max_chars = kMaxExcerptChars);

// `text` with everything a terminal could act on escaped: control characters (C0, DEL, C1) as
// \n, \t or \xNN, and bytes that are not UTF-8 as \xNN. Printable UTF-8 (°, ², Greek) stays.
std::string printable(std::string_view text);

// The longest name of one file or folder that Linux file systems take, in bytes (NAME_MAX).
inline constexpr std::size_t kMaxFileNameBytes = 255;

// Why `name` cannot name a node, element, material, driver or study case, or "" when it can.
// Names become CSV column headers (history.csv, study.csv), JSON keys and folder names: they
// must be non-empty UTF-8 of at most kMaxFileNameBytes, without control characters, commas or
// double quotes.
std::string name_problem(std::string_view name);

}  // namespace deploydyn::io
