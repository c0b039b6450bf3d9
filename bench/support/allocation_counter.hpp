#pragma once
// Counts the process's heap allocations (malloc, calloc, realloc, aligned allocations; operator
// new and Eigen go through them), to check that a time step does no heap work. Works by
// interposing glibc's allocator in the benchmark program; not built with sanitizers.

namespace deploydyn::bench {

long heap_allocations();  // since the program started

}  // namespace deploydyn::bench
