// In-place sorting without a heap: insertion sort for the short runs DRAW and CUT usually see
// (a handful of crossings per edge), heapsort beyond that so one edge crossed by thousands of
// others still costs O(k log k), never O(k^2). Neither needs extra memory.
#pragma once
#include <stddef.h>

namespace haloplot {

template <typename T, typename Less>
void insertion_sort(T* a, size_t n, Less less) {
  for (size_t i = 1; i < n; ++i) {
    T v = a[i];
    size_t j = i;
    while (j > 0 && less(v, a[j - 1])) {
      a[j] = a[j - 1];
      --j;
    }
    a[j] = v;
  }
}

template <typename T, typename Less>
void sift_down(T* a, size_t root, size_t n, Less less) {
  for (;;) {
    size_t child = 2 * root + 1;
    if (child >= n) return;
    if (child + 1 < n && less(a[child], a[child + 1])) ++child;
    if (!less(a[root], a[child])) return;
    T t = a[root];
    a[root] = a[child];
    a[child] = t;
    root = child;
  }
}

template <typename T, typename Less>
void heap_sort(T* a, size_t n, Less less) {
  if (n < 2) return;
  for (size_t i = n / 2; i-- > 0;) sift_down(a, i, n, less);
  for (size_t end = n - 1; end > 0; --end) {
    T t = a[0];
    a[0] = a[end];
    a[end] = t;
    sift_down(a, 0, end, less);
  }
}

// Below this size insertion sort wins on every target we measured; above it, heapsort's
// O(k log k) guards against one edge crossed by very many others.
inline constexpr size_t kInsertionSortLimit = 24;

template <typename T, typename Less>
void sort_in_place(T* a, size_t n, Less less) {
  if (n <= kInsertionSortLimit)
    insertion_sort(a, n, less);
  else
    heap_sort(a, n, less);
}

}  // namespace haloplot
