#pragma once
// RFC 4648 base64, for binary data inside text files: the VTK frames' arrays
// (output/vtk_writer.cpp) and the run report's (report/run_report.cpp).

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deploydyn {

// Appends the base64 text of `bytes` to `out` (with '=' padding).
void append_base64(std::string& out, std::span<const unsigned char> bytes);

// The bytes of base64 `text` (padded or not; white space is not allowed), or nothing when it
// is not base64: what the report reads back from a modal run's VTK frames.
std::optional<std::vector<unsigned char>> decode_base64(std::string_view text);

}  // namespace deploydyn
