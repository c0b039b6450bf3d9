#pragma once
// One table per enumeration of how model files, results and messages spell its values, so that
// the loader, the writers and the Python module read the same names instead of each keeping a
// list (or an array indexed by the enum) that must stay in step with the others.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace deploydyn {

template <class Enum>
struct NamedValue {
  Enum value;
  std::string_view name;
};

template <class Enum, std::size_t N>
class NameTable {
 public:
  constexpr explicit NameTable(std::array<NamedValue<Enum>, N> entries) : entries_(entries) {}

  // The name of a value of the table (every value of the enumeration has one).
  constexpr std::string_view name(Enum value) const {
    for (const NamedValue<Enum>& entry : entries_) {
      if (entry.value == value) return entry.name;
    }
    return "?";
  }
  constexpr std::optional<Enum> find(std::string_view name) const {
    for (const NamedValue<Enum>& entry : entries_) {
      if (entry.name == name) return entry.value;
    }
    return std::nullopt;
  }
  // The names in table order (messages list them in this order).
  constexpr std::array<std::string_view, N> names() const {
    std::array<std::string_view, N> names{};
    for (std::size_t i = 0; i < N; ++i) names[i] = entries_[i].name;
    return names;
  }
  constexpr Enum value(std::size_t i) const { return entries_[i].value; }

 private:
  std::array<NamedValue<Enum>, N> entries_;
};

}  // namespace deploydyn
