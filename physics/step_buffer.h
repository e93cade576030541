// The solver's per-step arrays, sized anew every step and written whole before they are read: a
// larger step's array is allocated at its size and an eighth more, its old contents dropped first
// (never copied, never doubled: a 5050-box pyramid's lanes are 10 MB, and one more manifold than
// last step would otherwise double them and hold the old beside the new while it copies).
#pragma once
#include <cstddef>
#include <vector>

namespace impulse::physics {

template <class T>
void resize_for_step(std::vector<T>& v, size_t n) {
  if (n > v.capacity()) {
    std::vector<T>().swap(v);
    v.reserve(n + n / 8);
  }
  v.resize(n);
}

}  // namespace impulse::physics
