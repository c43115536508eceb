#pragma once
// The inverse of a small square matrix (fixed size N, row-major) by Gauss-Jordan elimination with partial pivoting,
// for the Kalman filter's innovation covariance. Pure; interrupt-safe as long as no other task writes the operands.
//
// The elimination works on a copy m of a and on w, which starts as the identity. For each column col = 0 .. N - 1:
//   pivot    the row p >= col with the largest |m[p][col]| (the first one on ties); rows p and col of m and of w are
//            swapped (nothing happens when p == col)
//   scale    with pivot = m[col][col]: m[col][j] = divide(m[col][j], pivot) and w[col][j] = divide(w[col][j], pivot)
//            for j = 0 .. N - 1
//   clear    for every other row r in increasing order, with factor = m[r][col] read before the row changes:
//            m[r][j] = subtract(m[r][j], multiply(factor, m[col][j])) and the same for w, j = 0 .. N - 1
// At the end w is the inverse. The matrix counts as singular, and the result is false with `inverse` left untouched,
// when a pivot is not above 0 in magnitude: exactly 0 after rounding, or a NaN (the search starts from the diagonal
// element, so a NaN there makes the matrix singular). A nearly singular matrix inverts to very large values; the caller
// decides what is too large.

#include <array>
#include <cstddef>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"
#include "duet/blocks/nonlinear.hpp"

namespace duet::blocks {

// Writes a^-1 to inverse (both n x n, row-major) and returns true, or returns false for a singular a (see above).
// scratch holds 2 n^2 values (the working copies m and w). Preconditions: the arrays hold that many values; inverse may
// be a itself (a is copied before anything is written). The sizes are run-time values so that the simulation's
// interpreter runs this very code; the generated code calls the fixed-size form below. The loops are unrolled
// (#pragma GCC unroll) so that with a size known at compile time they vanish and m and w stay in registers: a 2 x 2
// inverse is then some 40 instructions instead of loops over memory.
template <Floating T>
[[nodiscard]] constexpr bool matrix_inverse(const T* a, T* inverse, std::size_t n, T* scratch) {
  T* m = scratch;
  T* w = scratch + n * n;
#pragma GCC unroll 8
  for (std::size_t i = 0; i < n * n; ++i) {
    m[i] = a[i];
    w[i] = T{0};
  }
#pragma GCC unroll 8
  for (std::size_t i = 0; i < n; ++i) w[i * n + i] = T{1};

#pragma GCC unroll 8
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot_row = col;
    T largest = absolute(m[col * n + col]);
#pragma GCC unroll 8
    for (std::size_t r = col + 1; r < n; ++r) {
      const T magnitude = absolute(m[r * n + col]);
      if (magnitude > largest) {
        largest = magnitude;
        pivot_row = r;
      }
    }
    if (!(largest > T{0})) return false;
    if (pivot_row != col) {
#pragma GCC unroll 8
      for (std::size_t j = 0; j < n; ++j) {
        const T m_swap = m[col * n + j];
        m[col * n + j] = m[pivot_row * n + j];
        m[pivot_row * n + j] = m_swap;
        const T w_swap = w[col * n + j];
        w[col * n + j] = w[pivot_row * n + j];
        w[pivot_row * n + j] = w_swap;
      }
    }

    const T pivot = m[col * n + col];
#pragma GCC unroll 8
    for (std::size_t j = 0; j < n; ++j) {
      m[col * n + j] = divide(m[col * n + j], pivot);
      w[col * n + j] = divide(w[col * n + j], pivot);
    }

#pragma GCC unroll 8
    for (std::size_t r = 0; r < n; ++r) {
      if (r == col) continue;
      const T factor = m[r * n + col];
#pragma GCC unroll 8
      for (std::size_t j = 0; j < n; ++j) {
        m[r * n + j] = subtract(m[r * n + j], multiply(factor, m[col * n + j]));
        w[r * n + j] = subtract(w[r * n + j], multiply(factor, w[col * n + j]));
      }
    }
  }

#pragma GCC unroll 8
  for (std::size_t i = 0; i < n * n; ++i) inverse[i] = w[i];
  return true;
}

// The same for a fixed size N, with its scratch on the stack.
template <Floating T, std::size_t N>
[[nodiscard]] constexpr bool matrix_inverse(const T* a, T* inverse) {
  std::array<T, 2 * N * N> scratch;  // written before it is read
  return matrix_inverse(a, inverse, N, scratch.data());
}

}  // namespace duet::blocks
