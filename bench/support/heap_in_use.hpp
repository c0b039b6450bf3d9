#pragma once
// Bytes the C/C++ heap holds now (glibc's mallinfo2): what the structures built since a
// baseline take.

#include <malloc.h>

namespace deploydyn::bench {

inline double heap_in_use_bytes() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks + info.hblkhd);
}

}  // namespace deploydyn::bench
