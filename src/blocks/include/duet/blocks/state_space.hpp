#pragma once
// Discrete state space (Simulink's Discrete State-Space) and state feedback u = -K x. Matrices are row-major:
// A (NX x NX), B (NX x NU), C (NY x NX), D (NY x NU), K (nu x nx).
//
// Each row of a matrix expression is one running sum, left to right from the first product, over the terms as they
// are written: for y = C x + D u,
//   y[r] = (((c[r][0] * x[0] + c[r][1] * x[1]) + ...) + d[r][0] * u[0]) + ...
// with acc = multiply(...) for the first term and acc = add(acc, multiply(...)) for each next one, as matrix_multiply
// sums; x(k+1) = A x + B u alike. That order is the result's rounding, so it is part of the contract.
// Preconditions: the arrays hold the sizes above; outputs overlap no input (they are written while inputs are read).
// DiscreteStateSpace is not interrupt-safe (one task owns it); state_feedback is pure.

#include <array>
#include <cstddef>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"

namespace duet::blocks {
namespace detail {

// m[row][0] * v[0] + ... + m[row][n - 1] * v[n - 1] for a row-major m with n columns, left to right from the first
// product (n == 0 gives 0). The second form continues a running sum: acc + m[row][0] * v[0] + ..., left to right
// (n == 0 gives acc).
template <Number T>
constexpr T row_times_vector(const T* m, std::size_t row, const T* v, std::size_t n) {
  if (n == 0) return T{0};
  T acc = multiply(m[row * n], v[0]);
  for (std::size_t j = 1; j < n; ++j) acc = add(acc, multiply(m[row * n + j], v[j]));
  return acc;
}

template <Number T>
constexpr T row_times_vector(T acc, const T* m, std::size_t row, const T* v, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) acc = add(acc, multiply(m[row * n + j], v[j]));
  return acc;
}

// The kernels for sizes known at run time (the simulation's interpreter calls them; the block below with its sizes).
// scratch holds nx values (the next state, computed whole before x changes).
template <Floating T>
constexpr void state_space_output(const T* x, std::size_t nx, std::size_t nu, std::size_t ny, const T* u, const T* c,
                                  const T* d, T* y) {
  for (std::size_t r = 0; r < ny; ++r) y[r] = row_times_vector(row_times_vector(c, r, x, nx), d, r, u, nu);
}

template <Floating T>
constexpr void state_space_update(T* x, std::size_t nx, std::size_t nu, const T* u, const T* a, const T* b,
                                  T* scratch) {
  for (std::size_t r = 0; r < nx; ++r) scratch[r] = row_times_vector(row_times_vector(a, r, x, nx), b, r, u, nu);
  for (std::size_t r = 0; r < nx; ++r) x[r] = scratch[r];
}

}  // namespace detail

// y(k) = C x(k) + D u(k); x(k+1) = A x(k) + B u(k). x starts as the aggregate-initialised state (zeros: at rest).
// NU may be 0 (no input; u, b and d are then not read).
template <Floating T, std::size_t NX, std::size_t NU, std::size_t NY>
struct DiscreteStateSpace {
  static_assert(NX >= 1 && NY >= 1, "DiscreteStateSpace: at least one state and one output");

  T x[NX];

  constexpr void output(const T* u, const T* c, const T* d, T* y) const {
    detail::state_space_output(x, NX, NU, NY, u, c, d, y);
  }

  constexpr void update(const T* u, const T* a, const T* b) {
    std::array<T, NX> next;  // written before it is read
    detail::state_space_update(x, NX, NU, u, a, b, next.data());
  }
};

// u = -K x for K (nu x nx) and x (nx): u[r] = negate(k[r][0] * x[0] + ... + k[r][nx - 1] * x[nx - 1]), the sum left to
// right from the first product; nx == 0 gives negate(0) = -0.0. Preconditions: u overlaps neither gain_k nor x.
template <Floating T>
constexpr void state_feedback(const T* gain_k, const T* x, std::size_t nu, std::size_t nx, T* u) {
  for (std::size_t r = 0; r < nu; ++r) u[r] = negate(detail::row_times_vector(gain_k, r, x, nx));
}

}  // namespace duet::blocks
