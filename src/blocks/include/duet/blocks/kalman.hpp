#pragma once
// Discrete Kalman filters (Simulink's Kalman Filter block, time-invariant, "use the current measurement"): the output
// is the filtered estimate x[k|k], which already uses the measurement y(k) of the same step. The model is
//   x(k+1) = A x(k) + B u(k) + G w(k),   y(k) = C x(k) + v(k),   E[w w^T] = Q (NW x NW), E[v v^T] = R (NY x NY)
// with A (NX x NX), B (NX x nu), C (NY x NX), G (NX x NW), all row-major; the B u term is optional (update overloads).
//
// The state holds the PREDICTION for the current step, x = x[k|k-1] and p = P[k|k-1]; aggregate-initialise it with the
// initial estimate and covariance, e.g. KalmanFilter<float, 2, 2, 1>{{0.0F, 0.0F}, {1.0F, 0.0F, 0.0F, 1.0F}}.
// One step computes, in this order (every product with matrix_multiply, every sum and difference element by element):
//   1. K = P C^T (C P C^T + R)^-1:  Ct = transpose(C); PCt = P * Ct; S = C * PCt; S = add(S, R) element by element;
//      S^-1 with matrix_inverse (Gauss-Jordan); K = PCt * S^-1. If S is singular, K = 0: the prediction passes
//      through unchanged and P only grows by the process noise.
//   2. x[k|k] = x + K (y - C x):  Cx = C * x; e = subtract(y, Cx); x[k|k] = add(x, K * e)          (output())
//   3. P[k|k] = (I - K C) P:  KC = K * C; M = subtract(I, KC) element by element; P[k|k] = M * P
//   4. x[k+1|k] = A x[k|k] (+ B u): per row one running sum left to right, as DiscreteStateSpace sums it
//   5. P[k+1|k] = A P[k|k] A^T + G Q G^T:  (A * P[k|k]) * transpose(A), (G * Q) * transpose(G), then add elementwise
// output() computes steps 1 and 2 and keeps K (member `gain`); update() computes 2 to 5 with that K, so a step calls
// output() before update(), as every model step does. The Joseph form and symmetrisation are deliberately absent:
// they are not what Simulink computes.
//
// SteadyStateKalmanFilter is the same filter with a constant gain K (NX x NY) computed beforehand (e.g. on the host
// with the discrete Riccati equation): steps 2 and 4 only, no covariance.
// Preconditions: arrays hold the sizes above; estimate overlaps no input. Not interrupt-safe: one task owns a filter.
// The work is done by kernels in detail:: with run-time sizes (the simulation's interpreter calls them directly); their
// loops are unrolled for the fixed sizes of generated code, as matrix.hpp's are.

#include <array>
#include <cstddef>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"
#include "duet/blocks/matrix.hpp"
#include "duet/blocks/matrix_inverse.hpp"
#include "duet/blocks/state_space.hpp"

namespace duet::blocks {
namespace detail {

// The kernels take their sizes at run time and their temporaries from `scratch`, so that the simulation's interpreter
// runs this very code with the sizes of a model's block; the filters below call them with their fixed sizes.

// How many values of scratch kalman_output and kalman_update need (the larger of the two).
constexpr std::size_t kalman_scratch_size(std::size_t nx, std::size_t ny, std::size_t nw) {
  const std::size_t output = 2 * nx * ny + 4 * ny * ny;
  const std::size_t update = nx + (nx + ny) + 6 * nx * nx + 2 * nx * nw;
  return output > update ? output : update;
}

// Step 1: gain (nx x ny) = P C^T (C P C^T + R)^-1, or zeros for a singular C P C^T + R. scratch: 2 nx ny + 4 ny^2.
template <Floating T>
constexpr void kalman_gain(const T* p, const T* c, const T* r, std::size_t nx, std::size_t ny, T* gain, T* scratch) {
  T* c_transposed = scratch;                            // ny x nx
  T* p_c_transposed = c_transposed + ny * nx;           // nx x ny
  T* innovation_covariance = p_c_transposed + nx * ny;  // ny x ny
  T* inverse = innovation_covariance + ny * ny;         // ny x ny
  T* inverse_scratch = inverse + ny * ny;               // 2 ny^2
  matrix_transpose(c, c_transposed, ny, nx);
  matrix_multiply(p, c_transposed, p_c_transposed, nx, nx, ny);
  matrix_multiply(c, p_c_transposed, innovation_covariance, ny, nx, ny);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < ny * ny; ++i) innovation_covariance[i] = add(innovation_covariance[i], r[i]);
  if (!matrix_inverse(innovation_covariance, inverse, ny, inverse_scratch)) {
#pragma GCC unroll 8
    for (std::size_t i = 0; i < nx * ny; ++i) gain[i] = T{0};  // K = 0
    return;
  }
  matrix_multiply(p_c_transposed, inverse, gain, nx, ny, ny);
}

// Step 2: estimate = x + K (y - C x). scratch: nx + ny.
template <Floating T>
constexpr void kalman_correct(const T* x, const T* y, const T* c, const T* gain_k, std::size_t nx, std::size_t ny,
                              T* estimate, T* scratch) {
  T* innovation = scratch;
  T* correction = scratch + ny;
  matrix_multiply(c, x, innovation, ny, nx, 1);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < ny; ++i) innovation[i] = subtract(y[i], innovation[i]);
  matrix_multiply(gain_k, innovation, correction, nx, ny, 1);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < nx; ++i) estimate[i] = add(x[i], correction[i]);
}

// Step 4: x = A estimate + B u, one running sum per row (nu == 0: A estimate alone).
template <Floating T>
constexpr void kalman_predict_state(const T* estimate, const T* u, std::size_t nu, const T* a, const T* b,
                                    std::size_t nx, T* x) {
#pragma GCC unroll 8
  for (std::size_t i = 0; i < nx; ++i) x[i] = row_times_vector(row_times_vector(a, i, estimate, nx), b, i, u, nu);
}

// Steps 1 and 2: gain (nx x ny, kept for kalman_update) and estimate = x[k|k].
template <Floating T>
constexpr void kalman_output(const T* x, const T* p, std::size_t nx, std::size_t ny, const T* y, const T* c, const T* r,
                             T* gain, T* estimate, T* scratch) {
  kalman_gain(p, c, r, nx, ny, gain, scratch);
  kalman_correct(x, y, c, gain, nx, ny, estimate, scratch);
}

// Steps 2 to 5 with the gain kalman_output computed in the same step: x, p become x[k+1|k], P[k+1|k].
template <Floating T>
constexpr void kalman_update(T* x, T* p, std::size_t nx, std::size_t ny, std::size_t nw, const T* y, const T* u,
                             std::size_t nu, const T* a, const T* b, const T* c, const T* g, const T* q, const T* gain,
                             T* scratch) {
  T* estimate = scratch;
  T* correct_scratch = estimate + nx;
  T* reduction = correct_scratch + nx + ny;  // nx x nx, then the temporaries of steps 3 and 5
  T* p_filtered = reduction + nx * nx;
  T* a_transposed = p_filtered + nx * nx;
  T* a_p = a_transposed + nx * nx;
  T* propagated = a_p + nx * nx;
  T* process_noise = propagated + nx * nx;
  T* g_transposed = process_noise + nx * nx;  // nw x nx
  T* g_q = g_transposed + nw * nx;            // nx x nw
  kalman_correct(x, y, c, gain, nx, ny, estimate, correct_scratch);

  // P[k|k] = (I - K C) P[k|k-1]
  matrix_multiply(gain, c, reduction, nx, ny, nx);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < nx; ++i) {
#pragma GCC unroll 8
    for (std::size_t j = 0; j < nx; ++j) reduction[i * nx + j] = subtract(i == j ? T{1} : T{0}, reduction[i * nx + j]);
  }
  matrix_multiply(reduction, p, p_filtered, nx, nx, nx);

  kalman_predict_state(estimate, u, nu, a, b, nx, x);

  // P[k+1|k] = (A P[k|k]) A^T + (G Q) G^T
  matrix_transpose(a, a_transposed, nx, nx);
  matrix_multiply(a, p_filtered, a_p, nx, nx, nx);
  matrix_multiply(a_p, a_transposed, propagated, nx, nx, nx);
  matrix_transpose(g, g_transposed, nx, nw);
  matrix_multiply(g, q, g_q, nx, nw, nw);
  matrix_multiply(g_q, g_transposed, process_noise, nx, nw, nx);
#pragma GCC unroll 8
  for (std::size_t i = 0; i < nx * nx; ++i) p[i] = add(propagated[i], process_noise[i]);
}

// The steady-state filter's steps 2 and 4. scratch: nx + ny (output), 2 nx + ny (update).
template <Floating T>
constexpr void steady_state_kalman_output(const T* x, std::size_t nx, std::size_t ny, const T* y, const T* c,
                                          const T* gain_k, T* estimate, T* scratch) {
  kalman_correct(x, y, c, gain_k, nx, ny, estimate, scratch);
}

template <Floating T>
constexpr void steady_state_kalman_update(T* x, std::size_t nx, std::size_t ny, const T* y, const T* u, std::size_t nu,
                                          const T* a, const T* b, const T* c, const T* gain_k, T* scratch) {
  T* estimate = scratch;
  kalman_correct(x, y, c, gain_k, nx, ny, estimate, scratch + nx);
  kalman_predict_state(estimate, u, nu, a, b, nx, x);
}

}  // namespace detail

template <Floating T, std::size_t NX, std::size_t NY, std::size_t NW>
struct KalmanFilter {
  static_assert(NX >= 1 && NY >= 1 && NW >= 1, "KalmanFilter: at least one state, measurement and noise input");
  static constexpr std::size_t scratch_size = detail::kalman_scratch_size(NX, NY, NW);

  T x[NX];          // x[k|k-1]
  T p[NX * NX];     // P[k|k-1], row-major
  T gain[NX * NY];  // K of the step: output() computes it, update() uses it

  // estimate = x[k|k] (NX values); keeps K for update().
  constexpr void output(const T* y, const T* c, const T* r, T* estimate) {
    std::array<T, scratch_size> scratch;  // the kernels write before they read: no zeroing
    detail::kalman_output(x, p, NX, NY, y, c, r, gain, estimate, scratch.data());
  }

  // x, p become x[k+1|k], P[k+1|k], with the K output() computed in this step (a step calls output() first).
  constexpr void update(const T* y, const T* a, const T* c, const T* g, const T* q) {
    // The kernel itself rather than the overload below: through it the count of inputs, 0, stayed a run-time value
    // and GCC kept a loop over B u that never runs.
    std::array<T, scratch_size> scratch;  // the kernels write before they read: no zeroing
    detail::kalman_update<T>(x, p, NX, NY, NW, y, nullptr, 0, a, nullptr, c, g, q, gain, scratch.data());
  }

  // The same with an input: x[k+1|k] = A x[k|k] + B u, for u (nu values) and B (NX x nu).
  constexpr void update(const T* y, const T* u, std::size_t nu, const T* a, const T* b, const T* c, const T* g,
                        const T* q) {
    std::array<T, scratch_size> scratch;  // the kernels write before they read: no zeroing
    detail::kalman_update(x, p, NX, NY, NW, y, u, nu, a, b, c, g, q, gain, scratch.data());
  }
};

template <Floating T, std::size_t NX, std::size_t NY>
struct SteadyStateKalmanFilter {
  static_assert(NX >= 1 && NY >= 1, "SteadyStateKalmanFilter: at least one state and one measurement");

  T x[NX];  // x[k|k-1]

  // estimate = x[k|k] = x + K (y - C x) (NX values).
  constexpr void output(const T* y, const T* c, const T* gain_k, T* estimate) const {
    std::array<T, NX + NY> scratch;
    detail::steady_state_kalman_output(x, NX, NY, y, c, gain_k, estimate, scratch.data());
  }

  // x becomes x[k+1|k] = A x[k|k].
  constexpr void update(const T* y, const T* a, const T* c, const T* gain_k) {
    update(y, nullptr, 0, a, nullptr, c, gain_k);
  }

  // The same with an input: x[k+1|k] = A x[k|k] + B u, for u (nu values) and B (NX x nu).
  constexpr void update(const T* y, const T* u, std::size_t nu, const T* a, const T* b, const T* c, const T* gain_k) {
    std::array<T, 2 * NX + NY> scratch;
    detail::steady_state_kalman_update(x, NX, NY, y, u, nu, a, b, c, gain_k, scratch.data());
  }
};

}  // namespace duet::blocks
