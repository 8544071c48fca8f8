// In-place sorting without a heap: insertion sort for the short runs DRAW and CUT usually see
// (a handful of crossings per edge), heapsort beyond that so one edge crossed by thousands of
// others still costs O(k log k), never O(k^2). Neither needs extra memory. sort_total() is the
// quicker sort for long arrays whose order has no ties (see there).
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

namespace sort_detail {

template <typename T>
void swap_values(T& a, T& b) {
  T t = a;
  a = b;
  b = t;
}

// Introsort's loop: quicksort partitions (Hoare's, on the median of the first, middle and last
// values), the smaller part sorted by a call, the larger by the loop, so calls nest at most
// log2(n) deep; a part still long after `depth` partitions is heapsorted (O(n log n) whatever
// the input), a short one insertion-sorted.
template <typename T, typename Less>
void intro_sort(T* a, size_t n, unsigned depth, Less less) {
  while (n > kInsertionSortLimit) {
    if (depth == 0) {
      heap_sort(a, n, less);
      return;
    }
    --depth;
    T* mid = a + n / 2;
    T* last = a + n - 1;
    if (less(*mid, *a)) swap_values(*mid, *a);
    if (less(*last, *mid)) swap_values(*last, *mid);
    if (less(*mid, *a)) swap_values(*mid, *a);
    swap_values(*a, *mid);  // the median first: every part then holds at least one value
    const T pivot = *a;
    size_t i = 0, j = n;
    for (bool first = true;; first = false) {
      if (!first) ++i;
      while (less(a[i], pivot)) ++i;
      do --j;
      while (less(pivot, a[j]));
      if (i >= j) break;
      swap_values(a[i], a[j]);
    }
    // [0, j] holds no value above the pivot, (j, n) none below; both are shorter than n.
    const size_t left = j + 1, right = n - left;
    if (left < right) {
      intro_sort(a, left, depth, less);
      a += left;
      n = right;
    } else {
      intro_sort(a + left, right, depth, less);
      n = left;
    }
  }
  insertion_sort(a, n, less);
}

}  // namespace sort_detail

// Sorts by `less`, which must order the values totally: no two different values may compare
// equal (a last tie-break on an index does it; equal values that are the same bits are fine).
// Then every correct sort gives the same array, and this one (introsort: O(n log n) at worst,
// no extra memory) is several times quicker than heapsort on long arrays, whose sift-downs
// jump across memory.
template <typename T, typename Less>
void sort_total(T* a, size_t n, Less less) {
  unsigned depth = 0;
  for (size_t k = n; k > 1; k >>= 1) depth += 2;
  sort_detail::intro_sort(a, n, depth, less);
}

}  // namespace haloplot
