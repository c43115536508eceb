#pragma once
// Matrix product and transpose (Simulink's Product block in matrix mode, Transpose). Pure; interrupt-safe as long as no
// other task writes the operands or the result meanwhile.

#include <cstddef>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"

namespace duet::blocks {

// y = a * b for row-major a (rows x inner), b (inner x columns) and y (rows x columns):
//   y[r * columns + c] = sum over k = 0, 1, ..., inner - 1 of a[r * inner + k] * b[k * columns + c]
// accumulated in increasing k from the first product as acc = add(acc, multiply(a[...], b[...])); this order is the
// result's rounding, so it is part of the contract (starting from the first product rather than from 0 saves an
// addition and differs only in the sign of a zero sum). inner == 0 gives a zero matrix.
// Preconditions: the arrays hold at least those many elements, and y overlaps neither a nor b (y is written while a
// and b are still being read).
// The loops here and in the kernels built on them (matrix_inverse.hpp, kalman.hpp) are unrolled (#pragma GCC unroll):
// where the sizes are known at compile time, in generated code's fixed-size blocks, the products become straight-line
// code on registers; the interpreter's run-time sizes keep loops. Unrolling changes no operation or its order.
template <Number T>
constexpr void matrix_multiply(const T* a, const T* b, T* y, std::size_t rows, std::size_t inner, std::size_t columns) {
#pragma GCC unroll 8
  for (std::size_t r = 0; r < rows; ++r) {
#pragma GCC unroll 8
    for (std::size_t c = 0; c < columns; ++c) {
      T acc = inner == 0 ? T{0} : multiply(a[r * inner], b[c]);
#pragma GCC unroll 8
      for (std::size_t k = 1; k < inner; ++k) acc = add(acc, multiply(a[r * inner + k], b[k * columns + c]));
      y[r * columns + c] = acc;
    }
  }
}

// y = a^T for row-major a (rows x columns) and y (columns x rows): y[c * rows + r] = a[r * columns + c]. Copies only,
// so it computes nothing that could round. Precondition: y does not overlap a.
template <Element T>
constexpr void matrix_transpose(const T* a, T* y, std::size_t rows, std::size_t columns) {
#pragma GCC unroll 8
  for (std::size_t r = 0; r < rows; ++r) {
#pragma GCC unroll 8
    for (std::size_t c = 0; c < columns; ++c) y[c * rows + r] = a[r * columns + c];
  }
}

}  // namespace duet::blocks
