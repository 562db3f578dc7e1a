// Heap use of this benchmark process: malloc, calloc, realloc, free and the aligned forms are
// interposed (bench/heap_counter.cc) and every block counted as malloc_usable_size reports it,
// so a benchmark can report the peak its work needed above what was allocated before it.
#pragma once

#include <cstddef>

namespace usvid::bench {

std::size_t HeapInUse();
// The peak since the last ResetHeapPeak (or the start).
std::size_t HeapPeak();
void ResetHeapPeak();

}  // namespace usvid::bench
