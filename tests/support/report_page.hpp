#pragma once
// The data block of a report page (report/run_report.hpp) as the tests read it: the JSON of
// #deploydyn-data, its base64 Float32 arrays through an RFC 4648 decoder written apart from the
// program's encoder, and a colouring by name.

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace deploydyn::testing {

inline std::vector<unsigned char> decode_base64_independently(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    buffer = (buffer << 6) | static_cast<unsigned>(std::strchr(digits, c) - digits);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  return out;
}

// Little-endian Float32 values of a base64 string.
inline std::vector<float> float32_array(const nlohmann::json& base64) {
  const std::vector<unsigned char> bytes = decode_base64_independently(base64.get<std::string>());
  std::vector<float> values(bytes.size() / 4);
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), 4 * values.size());
  return values;
}

inline nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"deploydyn-data\">";
  const std::size_t start = html.find(open) + open.size();
  return nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
}

// The animation's colouring called `name` (report/member_colourings.hpp), or null.
inline nlohmann::json colouring(const nlohmann::json& animation, const std::string& name) {
  for (const auto& c : animation["colourings"]) {
    if (c["name"] == name) return c;
  }
  return nullptr;
}

}  // namespace deploydyn::testing
