#pragma once
// An element type's result quantities, named once. An enum names the slot of each quantity
// (what its results() writes: out[kForce] = …), and quantity_table places every entry of the
// type's table (ElementKind::quantities) at its slot, so that the order of the writes and of
// the table cannot drift apart. A slot named twice or out of range does not compile, nor does a
// table whose size is not the enum's count.

#include <array>
#include <cstddef>

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

struct SlotQuantity {
  int slot;  // an enumerator of the type's slots
  ResultQuantity quantity;
};

template <std::size_t N>
consteval std::array<ResultQuantity, N> quantity_table(const SlotQuantity (&entries)[N]) {
  std::array<ResultQuantity, N> table{};
  std::array<bool, N> named{};
  for (const SlotQuantity& entry : entries) {
    const auto k = static_cast<std::size_t>(entry.slot);
    if (entry.slot < 0 || k >= N || named[k]) throw "a result slot out of range or named twice";
    named[k] = true;
    table[k] = entry.quantity;
  }
  return table;
}

}  // namespace deploydyn
