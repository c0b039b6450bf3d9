#pragma once
// RFC 4648 base64, for binary data inside text files: the VTK frames' arrays
// (output/vtk_writer.cpp) and the run report's (report/run_report.cpp).

#include <span>
#include <string>

namespace deploydyn {

// Appends the base64 text of `bytes` to `out` (with '=' padding).
void append_base64(std::string& out, std::span<const unsigned char> bytes);

}  // namespace deploydyn
