#include "duet/model/interpreter.hpp"

#include <algorithm>
#include <cstring>
#include <deque>
#include <limits>

#include "block_semantics.hpp"
#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/average.hpp"
#include "duet/blocks/bytes.hpp"
#include "duet/blocks/convert.hpp"
#include "duet/blocks/interpolation.hpp"
#include "duet/blocks/kalman.hpp"
#include "duet/blocks/logic.hpp"
#include "duet/blocks/matrix.hpp"
#include "duet/blocks/nonlinear.hpp"
#include "duet/blocks/sources.hpp"
#include "duet/blocks/state.hpp"
#include "duet/blocks/state_space.hpp"
#include "duet/blocks/table.hpp"
#include "duet/blocks/transfer_function.hpp"
#include "duet/blocks/trigonometry.hpp"
#include "duet/model/data_type.hpp"
#include "typed.hpp"
#include "user_code.hpp"

namespace duet::model {

// Memory laid out like the generated structures: each signal and parameter at an aligned offset.
struct Interpreter::Storage {
  std::vector<std::size_t> signal_offset;
  std::vector<double> signals;  // doubles: aligned for every element type
  std::byte* signal_base = nullptr;
  std::vector<std::size_t> parameter_offset;
  std::vector<double> working;
  std::vector<double> reference;
  const std::byte* page = nullptr;  // what the blocks read: working or reference
  const std::byte* working_base = nullptr;
  std::deque<std::vector<double>> literals;    // each literal converted to its block's type
  std::deque<const std::byte*> literal_bases;  // stable pointers to them, for Operand
};

namespace {

using Storage = Interpreter::Storage;

std::size_t layout(std::vector<std::size_t>& offsets, std::size_t bytes, std::size_t alignment, std::size_t& end) {
  end = (end + alignment - 1) / alignment * alignment;
  offsets.push_back(end);
  end += bytes;
  return end;
}

// Reads elements of a signal, a parameter or a literal through a base pointer that may change (the parameter page).
template <typename T>
struct Operand {
  const std::byte* const* base = nullptr;
  std::size_t offset = 0;
  bool scalar = true;

  T operator[](std::size_t element) const {
    T value;
    std::memcpy(&value, *base + offset + (scalar ? 0 : element) * sizeof(T), sizeof(T));
    return value;
  }
  [[nodiscard]] std::span<const T> all(std::size_t count) const {
    return {reinterpret_cast<const T*>(*base + offset), count};
  }
};

class Compiler {
 public:
  Compiler(const Program& program, Storage& storage, plant::Plant& plant)
      : program_(program), storage_(storage), plant_(plant) {}

  template <typename T>
  T* output(const ProgramBlock& block, std::size_t k) const {
    return reinterpret_cast<T*>(storage_.signal_base + storage_.signal_offset[block.outputs[k]]);
  }

  template <typename T>
  Operand<T> signal(std::size_t index) const {
    const ProgramSignal& signal = program_.signals[index];
    if (signal.parameter) {
      return {&storage_.page, storage_.parameter_offset[*signal.parameter], signal.type.elements() == 1};
    }
    return {&storage_.signal_base, storage_.signal_offset[index], signal.type.elements() == 1};
  }

  template <typename T>
  Operand<T> input(const ProgramBlock& block, std::size_t k) const {
    return signal<T>(block.inputs[k]);
  }

  // A block parameter as T: a tunable parameter read from the current page, or a literal converted once.
  template <typename T>
  Operand<T> argument(const ProgramBlock& block, const std::string& name, double fallback) {
    const Argument* given = block.argument(name);
    if (given != nullptr && given->kind == Argument::Kind::parameter) {
      return {&storage_.page, storage_.parameter_offset[given->parameter], given->value.elements.size() == 1};
    }
    const std::vector<double> values = given != nullptr ? given->value.elements : std::vector<double>{fallback};
    std::vector<double>& memory = storage_.literals.emplace_back((values.size() * sizeof(T) + 7) / 8 + 1);
    for (std::size_t element = 0; element < values.size(); ++element) {
      const T value = blocks::convert<T>(values[element]);
      std::memcpy(reinterpret_cast<std::byte*>(memory.data()) + element * sizeof(T), &value, sizeof(T));
    }
    const std::byte*& base = storage_.literal_bases.emplace_back(reinterpret_cast<const std::byte*>(memory.data()));
    return {&base, 0, values.size() == 1};
  }

  std::size_t elements_out(const ProgramBlock& block, std::size_t k = 0) const {
    return program_.signals[block.outputs[k]].type.elements();
  }
  std::size_t elements_in(const ProgramBlock& block, std::size_t k = 0) const {
    return program_.signals[block.inputs[k]].type.elements();
  }
  DataType type_out(const ProgramBlock& block, std::size_t k = 0) const {
    return program_.signals[block.outputs[k]].type.type;
  }
  DataType type_in(const ProgramBlock& block, std::size_t k = 0) const {
    return program_.signals[block.inputs[k]].type.type;
  }
  const Program& program() const { return program_; }
  plant::Plant& plant() const { return plant_; }

 private:
  const Program& program_;
  Storage& storage_;
  plant::Plant& plant_;
};

using Phases = std::pair<std::function<void()>, std::function<void()>>;  // output, update
using Reset = std::function<void()>;

struct Compiled {
  Phases phases;
  Reset reset;
};

constexpr double infinity = std::numeric_limits<double>::infinity();

// Element-wise y = f(inputs...) on blocks computing in their output's type.
template <typename T, typename Function>
Phases elementwise(Compiler& c, const ProgramBlock& block, Function function) {
  T* y = c.output<T>(block, 0);
  const std::size_t n = c.elements_out(block);
  return {[y, n, function] {
            for (std::size_t i = 0; i < n; ++i) y[i] = function(i);
          },
          {}};
}

template <typename T>
Compiled arithmetic(Compiler& c, const ProgramBlock& block) {
  if constexpr (!blocks::Number<T>) {
    return {};
  } else {
    const std::string& type = block.type();
    if (type == "Gain") {
      const Operand<T> u = c.input<T>(block, 0);
      const Operand<T> k = c.argument<T>(block, "k", 1);
      return {elementwise<T>(c, block, [u, k](std::size_t i) { return blocks::gain(u[i], k[i]); }), {}};
    }
    if (type == "Sum" || type == "Product") {
      std::vector<Operand<T>> inputs;
      for (std::size_t k = 0; k < block.inputs.size(); ++k) inputs.push_back(c.input<T>(block, k));
      const bool sum = type == "Sum";
      const std::string signs = sum ? sum_signs(block) : product_signs(block);
      return {elementwise<T>(c, block,
                             [inputs, signs, sum](std::size_t i) {
                               if (!sum) {
                                 T y = signs[0] == '/' ? blocks::divide(T{1}, inputs[0][i]) : inputs[0][i];
                                 for (std::size_t k = 1; k < inputs.size(); ++k) {
                                   y = signs[k] == '/' ? blocks::divide(y, inputs[k][i])
                                                       : blocks::multiply(y, inputs[k][i]);
                                 }
                                 return y;
                               }
                               T y = signs[0] == '-' ? blocks::negate(inputs[0][i]) : inputs[0][i];
                               for (std::size_t k = 1; k < inputs.size(); ++k) {
                                 y = signs[k] == '-' ? blocks::subtract(y, inputs[k][i]) : blocks::add(y, inputs[k][i]);
                               }
                               return y;
                             }),
              {}};
    }
    if (type == "Saturation") {
      const Operand<T> u = c.input<T>(block, 0);
      const Operand<T> lower = c.argument<T>(block, "lower", -infinity);
      const Operand<T> upper = c.argument<T>(block, "upper", infinity);
      return {elementwise<T>(c, block,
                             [u, lower, upper](std::size_t i) { return blocks::saturate(u[i], lower[i], upper[i]); }),
              {}};
    }
    if (type == "Abs") {
      const Operand<T> u = c.input<T>(block, 0);
      return {elementwise<T>(c, block, [u](std::size_t i) { return blocks::absolute(u[i]); }), {}};
    }
    if (type == "Sign") {
      const Operand<T> u = c.input<T>(block, 0);
      return {elementwise<T>(c, block, [u](std::size_t i) { return blocks::sign(u[i]); }), {}};
    }
    if (type == "MinMax") {
      std::vector<Operand<T>> inputs;
      for (std::size_t k = 0; k < block.inputs.size(); ++k) inputs.push_back(c.input<T>(block, k));
      const bool maximum = block.argument("function")->text == "max";
      return {elementwise<T>(c, block,
                             [inputs, maximum](std::size_t i) {
                               T y = inputs[0][i];
                               for (std::size_t k = 1; k < inputs.size(); ++k) {
                                 y = maximum ? blocks::maximum(y, inputs[k][i]) : blocks::minimum(y, inputs[k][i]);
                               }
                               return y;
                             }),
              {}};
    }
    if (type == "MatrixMultiply") {
      const Operand<T> a = c.input<T>(block, 0);
      const Operand<T> b = c.input<T>(block, 1);
      const MatrixSizes sizes = matrix_sizes(c.program(), block);
      T* y = c.output<T>(block, 0);
      return {{[a, b, y, sizes] {
                 blocks::matrix_multiply(a.all(0).data(), b.all(0).data(), y, sizes.rows, sizes.inner, sizes.columns);
               },
               {}},
              {}};
    }
    if (type == "Counter") {
      auto counter = std::make_shared<blocks::Counter<T>>();
      const Operand<T> limit = c.argument<T>(block, "limit", 0);
      const Operand<T> initial = c.argument<T>(block, "initial", 0);
      T* y = c.output<T>(block, 0);
      return {{[counter, y] { *y = counter->output(); }, [counter, limit] { counter->update(limit[0]); }},
              [counter, initial] { counter->count = initial[0]; }};
    }
    if constexpr (blocks::Floating<T>) return floating<T>(c, block);
    return {};
  }
}

// The blocks whose generated state has its size as a template argument run here on the block library's kernels with
// sizes known at run time (the generated structures call the same kernels, so both compute alike).
template <typename T>
Compiled sized(Compiler& c, const ProgramBlock& block) {
  const std::string& type = block.type();
  T* y = c.output<T>(block, 0);
  const std::size_t n_in = c.elements_in(block);
  const std::size_t n_out = c.elements_out(block);
  const Operand<T> u = c.input<T>(block, 0);
  const auto matrix = [&](const char* name) { return c.argument<T>(block, name, 0); };
  const auto size = [&](const char* name) { return argument_size(c.program(), block, name); };
  const auto data = [](const Operand<T>& operand) { return operand.all(0).data(); };
  static constexpr const T* no_input = nullptr;  // the filters' B u term: the blocks have no input u
  if (type == "TransferFunction") {
    const std::size_t order = size("denominator").elements - 1;
    auto state = std::make_shared<std::vector<T>>(order);
    const Operand<T> numerator = matrix("numerator");
    const Operand<T> denominator = matrix("denominator");
    return {{[state, y, u, numerator, denominator, data] {
               *y = blocks::detail::transfer_function_output(state->data(), state->size(), u[0], data(numerator),
                                                             data(denominator));
             },
             [state, u, numerator, denominator, data] {
               blocks::detail::transfer_function_update(state->data(), state->size(), u[0], data(numerator),
                                                        data(denominator));
             }},
            [state] { std::fill(state->begin(), state->end(), T{0}); }};
  }
  const Operand<T> initial = c.argument<T>(block, "initial", 0);
  if (type == "MovingAverage") {
    const std::size_t window = block_window(block);
    auto state = std::make_shared<std::pair<std::vector<T>, std::uint32_t>>(std::vector<T>(window), 0U);
    return {{[state, y, u] {
               *y =
                   blocks::detail::moving_average_output(state->first.data(), state->second, state->first.size(), u[0]);
             },
             [state, u] {
               blocks::detail::moving_average_update(state->first.data(), state->second, state->first.size(), u[0]);
             }},
            [state, initial] {
              for (std::size_t i = 0; i < state->first.size(); ++i) state->first[i] = initial[i];
              state->second = 0;
            }};
  }
  const std::size_t nx = size("a").rows;
  auto x = std::make_shared<std::vector<T>>(nx);
  const Operand<T> a = matrix("a");
  const Operand<T> cm = matrix("c");
  const Reset reset_x = [x, initial] {
    for (std::size_t i = 0; i < x->size(); ++i) (*x)[i] = initial[i];
  };
  if (type == "StateSpace") {
    const Operand<T> b = matrix("b");
    const Operand<T> d = matrix("d");
    auto scratch = std::make_shared<std::vector<T>>(nx);
    return {{[x, y, u, cm, d, n_in, n_out, data] {
               blocks::detail::state_space_output(x->data(), x->size(), n_in, n_out, data(u), data(cm), data(d), y);
             },
             [x, u, a, b, n_in, scratch, data] {
               blocks::detail::state_space_update(x->data(), x->size(), n_in, data(u), data(a), data(b),
                                                  scratch->data());
             }},
            reset_x};
  }
  // KalmanFilter: steady state with a gain, or time-varying with its covariance.
  if (block.argument("gain") != nullptr) {
    const Operand<T> gain = matrix("gain");
    auto scratch = std::make_shared<std::vector<T>>(blocks::detail::kalman_scratch_size(nx, n_in, 1));
    return {{[x, y, u, cm, gain, n_in, scratch, data] {
               blocks::detail::steady_state_kalman_output(x->data(), x->size(), n_in, data(u), data(cm), data(gain), y,
                                                          scratch->data());
             },
             [x, u, a, cm, gain, n_in, scratch, data] {
               blocks::detail::steady_state_kalman_update(x->data(), x->size(), n_in, data(u), no_input, 0, data(a),
                                                          no_input, data(cm), data(gain), scratch->data());
             }},
            reset_x};
  }
  const std::size_t nw = size("g").columns;
  auto p = std::make_shared<std::vector<T>>(nx * nx);
  const Operand<T> g = matrix("g");
  const Operand<T> q = matrix("q");
  const Operand<T> r = matrix("r");
  const bool covariance_given = block.argument("covariance") != nullptr;
  const Operand<T> covariance = c.argument<T>(block, "covariance", 0);
  auto scratch = std::make_shared<std::vector<T>>(blocks::detail::kalman_scratch_size(nx, n_in, nw));
  auto gain = std::make_shared<std::vector<T>>(nx * n_in);  // K of the step, from output to update
  return {{[x, p, y, u, cm, r, n_in, gain, scratch, data] {
             blocks::detail::kalman_output(x->data(), p->data(), x->size(), n_in, data(u), data(cm), data(r),
                                           gain->data(), y, scratch->data());
           },
           [x, p, u, a, cm, g, q, n_in, nw, gain, scratch, data] {
             blocks::detail::kalman_update(x->data(), p->data(), x->size(), n_in, nw, data(u), no_input, 0, data(a),
                                           no_input, data(cm), data(g), data(q), gain->data(), scratch->data());
           }},
          [reset_x, p, nx, covariance_given, covariance] {
            reset_x();
            for (std::size_t i = 0; i < nx * nx; ++i) {
              (*p)[i] = covariance_given ? covariance[i] : (i % (nx + 1) == 0 ? T{1} : T{0});
            }
          }};
}

template <typename T>
Compiled floating(Compiler& c, const ProgramBlock& block) {
  const std::string& type = block.type();
  const std::size_t n = c.elements_out(block);
  const T period = blocks::convert<T>(block.period_s);
  T* y = c.output<T>(block, 0);
  const Operand<T> u = c.input<T>(block, 0);
  if (type == "Atan2") {
    const Operand<T> x = c.input<T>(block, 1);
    return {elementwise<T>(c, block, [u, x](std::size_t i) { return blocks::atan2(u[i], x[i]); }), {}};
  }
  if (type == "DeadZone") {
    const Operand<T> start = c.argument<T>(block, "start", 0);
    const Operand<T> end = c.argument<T>(block, "end", 0);
    return {
        elementwise<T>(c, block, [u, start, end](std::size_t i) { return blocks::dead_zone(u[i], start[i], end[i]); }),
        {}};
  }
  if (type == "Interpolation") {
    const std::size_t count = block.argument("breakpoints")->value.elements.size();
    const Operand<T> breakpoints = c.argument<T>(block, "breakpoints", 0);
    const Operand<T> table = c.argument<T>(block, "table", 0);
    const blocks::InterpolationMethod method = interpolation_method(block);
    const blocks::Extrapolation extrapolation = extrapolation_of(block);
    return {elementwise<T>(c, block,
                           [u, breakpoints, table, count, method, extrapolation](std::size_t i) {
                             return blocks::interpolate(method, extrapolation, breakpoints.all(count), table.all(count),
                                                        u[i]);
                           }),
            {}};
  }
  if (type == "DiscreteIntegrator") {
    auto states = std::make_shared<std::vector<blocks::DiscreteIntegrator<T>>>(n);
    const Operand<T> gain = c.argument<T>(block, "gain", 1);
    const Operand<T> initial = c.argument<T>(block, "initial", 0);
    const Operand<T> lower = c.argument<T>(block, "lower", -infinity);
    const Operand<T> upper = c.argument<T>(block, "upper", infinity);
    return {{[states, y] {
               for (std::size_t i = 0; i < states->size(); ++i) y[i] = (*states)[i].output();
             },
             [states, u, gain, period, lower, upper] {
               for (std::size_t i = 0; i < states->size(); ++i) {
                 (*states)[i].update(u[i], gain[i], period, lower[i], upper[i]);
               }
             }},
            [states, initial] {
              for (std::size_t i = 0; i < states->size(); ++i) (*states)[i].state = initial[i];
            }};
  }
  if (type == "DiscreteDerivative") {
    auto states = std::make_shared<std::vector<blocks::DiscreteDerivative<T>>>(n);
    const Operand<T> gain = c.argument<T>(block, "gain", 1);
    return {{[states, y, u, gain, period] {
               for (std::size_t i = 0; i < states->size(); ++i) y[i] = (*states)[i].output(u[i], gain[i], period);
             },
             [states, u] {
               for (std::size_t i = 0; i < states->size(); ++i) (*states)[i].update(u[i]);
             }},
            [states] {
              for (auto& state : *states) state.previous = T{0};
            }};
  }
  if (type == "TransferFunction" || type == "StateSpace" || type == "MovingAverage" || type == "KalmanFilter") {
    return sized<T>(c, block);
  }
  if (type == "Mean") {
    const std::size_t count = c.elements_in(block);
    return {{[y, u, count] { *y = blocks::mean(u.all(count).data(), count); }, {}}, {}};
  }
  if (type == "StateFeedback") {
    const std::size_t nx = c.elements_in(block);
    const Operand<T> k = c.argument<T>(block, "k", 0);
    return {{[y, u, k, n, nx] { blocks::state_feedback(k.all(n * nx).data(), u.all(nx).data(), n, nx, y); }, {}}, {}};
  }
  if (type == "FilteredDerivative") {
    auto states = std::make_shared<std::vector<blocks::FilteredDerivative<T>>>(n);
    const Operand<T> gain = c.argument<T>(block, "gain", 1);
    const Operand<T> coefficient = c.argument<T>(block, "n", pid_default_filter);
    return {{[states, y, u, gain, coefficient] {
               for (std::size_t i = 0; i < states->size(); ++i) {
                 y[i] = (*states)[i].output(u[i], gain[i], coefficient[i]);
               }
             },
             [states, u, gain, coefficient, period] {
               for (std::size_t i = 0; i < states->size(); ++i) {
                 (*states)[i].update(u[i], gain[i], coefficient[i], period);
               }
             }},
            [states] {
              for (auto& state : *states) state.filter = T{0};
            }};
  }
  if (type == "DiscretePid") {
    auto states = std::make_shared<std::vector<blocks::DiscretePid<T>>>(n);
    const bool clamping = anti_windup_clamping(block);
    const auto gain = [&](const char* name) {  // an external gain's input, or the parameter
      const auto k = input_of(block, name);
      return k ? c.input<T>(block, *k) : c.argument<T>(block, name, 0);
    };
    const std::array<Operand<T>, 6> gains{gain("p"),
                                          gain("i"),
                                          gain("d"),
                                          c.argument<T>(block, "n", pid_default_filter),
                                          c.argument<T>(block, "lower", -infinity),
                                          c.argument<T>(block, "upper", infinity)};
    const auto gains_of = [gains](std::size_t i) {
      return blocks::PidGains<T>{gains[0][i], gains[1][i], gains[2][i], gains[3][i], gains[4][i], gains[5][i]};
    };
    // Unconnected, the external reset is a literal false.
    const auto reset_input = input_of(block, "reset");
    const Operand<bool> reset = reset_input ? c.input<bool>(block, *reset_input) : c.argument<bool>(block, "", 0);
    return {{[states, y, u, gains_of, reset] {
               for (std::size_t i = 0; i < states->size(); ++i) {
                 y[i] = (*states)[i].output(u[i], gains_of(i), reset[i]);
               }
             },
             [states, u, gains_of, period, clamping, reset] {
               for (std::size_t i = 0; i < states->size(); ++i) {
                 if (clamping) {
                   (*states)[i].update_clamped(u[i], gains_of(i), period, reset[i]);
                 } else {
                   (*states)[i].update(u[i], gains_of(i), period, reset[i]);
                 }
               }
             }},
            [states] {
              for (auto& state : *states) state = {T{0}, T{0}};
            }};
  }
  return {};
}

// Step and PulseGenerator count their own steps; a boolean one computes in uint8 and converts.
template <typename T>
Compiled source(Compiler& c, const ProgramBlock& block) {
  using Value = std::conditional_t<std::is_same_v<T, bool>, std::uint8_t, T>;
  auto counter = std::make_shared<blocks::StepCounter>();
  T* y = c.output<T>(block, 0);
  const SourceSteps steps = source_steps(block);
  std::function<void()> output;
  if (block.type() == "Step") {
    const Operand<Value> initial = c.argument<Value>(block, "initial", 0);
    const Operand<Value> final_value = c.argument<Value>(block, "final", 1);
    output = [counter, y, steps, initial, final_value] {
      *y = blocks::convert<T>(blocks::step(counter->output(), steps.start, initial[0], final_value[0]));
    };
  } else {
    const Operand<Value> amplitude = c.argument<Value>(block, "amplitude", 1);
    output = [counter, y, steps, amplitude] {
      *y = blocks::convert<T>(blocks::pulse(counter->output(), steps.period, steps.width, steps.start, amplitude[0]));
    };
  }
  return {{output, [counter] { counter->update(); }}, [counter] { counter->k = 0; }};
}

// BytePack: each input's elements in order, each as its type's bytes; ByteUnpack: values from bytes at an offset.
Compiled bytes(Compiler& c, const ProgramBlock& block) {
  const blocks::Endian endian = endian_of(block);
  if (block.type() == "BytePack") {
    std::vector<std::function<void(std::uint8_t*)>> packs;
    for (std::size_t k = 0; k < block.inputs.size(); ++k) {
      packs.push_back(with_type(c.type_in(block, k), [&](auto tag) -> std::function<void(std::uint8_t*)> {
        using T = decltype(tag);
        const Operand<T> u = c.input<T>(block, k);
        const std::size_t n = c.elements_in(block, k);
        return [u, n, endian](std::uint8_t* at) {
          for (std::size_t i = 0; i < n; ++i) blocks::pack(u[i], endian, at + i * sizeof(T));
        };
      }));
    }
    std::vector<std::size_t> offsets;
    std::size_t at = 0;
    for (std::size_t k = 0; k < block.inputs.size(); ++k) {
      offsets.push_back(at);
      at += size_of(c.type_in(block, k)) * c.elements_in(block, k);
    }
    std::uint8_t* y = c.output<std::uint8_t>(block, 0);
    return {{[packs, offsets, y] {
               for (std::size_t k = 0; k < packs.size(); ++k) packs[k](y + offsets[k]);
             },
             {}},
            {}};
  }
  const Operand<std::uint8_t> u = c.input<std::uint8_t>(block, 0);
  const std::size_t offset = unpack_offset(block);
  return with_type(c.type_out(block), [&](auto tag) -> Compiled {
    using T = decltype(tag);
    T* y = c.output<T>(block, 0);
    const std::size_t n = c.elements_out(block);
    const std::size_t in = c.elements_in(block);
    return {{[u, y, n, in, offset, endian] {
               const std::uint8_t* bytes = u.all(in).data() + offset;
               for (std::size_t i = 0; i < n; ++i) y[i] = blocks::unpack<T>(bytes + i * sizeof(T), endian);
             },
             {}},
            {}};
  });
}

// Blocks that compute in any element type, booleans too.
template <typename T>
Compiled any_type(Compiler& c, const ProgramBlock& block) {
  const std::string& type = block.type();
  if (type == "Step" || type == "PulseGenerator") return source<T>(c, block);
  if (type == "Constant") {
    if (c.program().signals[block.outputs[0]].parameter) return {};  // the parameter itself: nothing to compute
    const Operand<T> value = c.argument<T>(block, "value", 0);
    return {elementwise<T>(c, block, [value](std::size_t i) { return value[i]; }), {}};
  }
  if (type == "UnitDelay") {
    const std::size_t n = c.elements_out(block);
    auto states = std::make_shared<std::vector<blocks::UnitDelay<T>>>(n);
    const Operand<T> initial = c.argument<T>(block, "initial", 0);
    const Operand<T> u = c.input<T>(block, 0);
    T* y = c.output<T>(block, 0);
    return {{[states, y] {
               for (std::size_t i = 0; i < states->size(); ++i) y[i] = (*states)[i].output();
             },
             [states, u] {
               for (std::size_t i = 0; i < states->size(); ++i) (*states)[i].update(u[i]);
             }},
            [states, initial] {
              for (std::size_t i = 0; i < states->size(); ++i) (*states)[i].state = initial[i];
            }};
  }
  if (type == "Switch") {
    const Operand<T> on = c.input<T>(block, 0);
    const Operand<T> off = c.input<T>(block, 2);
    return with_type(c.type_in(block, 1), [&](auto tag) -> Compiled {
      using C = decltype(tag);
      const Operand<C> decided = c.input<C>(block, 1);
      return {elementwise<T>(c, block,
                             [on, off, decided](std::size_t i) {
                               return blocks::select(blocks::convert<bool>(decided[i]), on[i], off[i]);
                             }),
              {}};
    });
  }
  if (type == "Selector" || type == "Demux") {
    const Operand<T> u = c.input<T>(block, 0);
    const std::size_t n = c.elements_in(block);
    if (type == "Demux") {
      std::vector<std::pair<T*, std::size_t>> outputs;
      for (std::size_t k = 0; k < block.outputs.size(); ++k) {
        outputs.emplace_back(c.output<T>(block, k), demux_element(block.output_ports[k]));
      }
      return {{[outputs, u] {
                 for (const auto& [y, element] : outputs) *y = u[element];
               },
               {}},
              {}};
    }
    T* y = c.output<T>(block, 0);
    return with_type(c.type_in(block, 1), [&](auto tag) -> Compiled {
      using I = decltype(tag);
      const Operand<I> index = c.input<I>(block, 1);
      return {{[y, u, n, index] { *y = blocks::element_at(u.all(n), index[0]); }, {}}, {}};
    });
  }
  if (type == "Lookup") {
    const Argument* table_argument = block.argument("table");
    const std::size_t n = table_argument->value.elements.size();
    const Operand<T> table = c.argument<T>(block, "table", 0);
    T* y = c.output<T>(block, 0);
    return with_type(c.type_in(block, 0), [&](auto tag) -> Compiled {
      using I = decltype(tag);
      const Operand<I> index = c.input<I>(block, 0);
      return {{[y, table, n, index] { *y = blocks::element_at(table.all(n), index[0]); }, {}}, {}};
    });
  }
  if (type == "Mux") {
    std::vector<std::pair<Operand<T>, std::size_t>> inputs;
    for (std::size_t k = 0; k < block.inputs.size(); ++k)
      inputs.emplace_back(c.input<T>(block, k), c.elements_in(block, k));
    T* y = c.output<T>(block, 0);
    return {{[inputs, y] {
               std::size_t at = 0;
               for (const auto& [u, count] : inputs) {
                 for (std::size_t i = 0; i < count; ++i) y[at++] = u[i];
               }
             },
             {}},
            {}};
  }
  return arithmetic<T>(c, block);
}

// Blocks whose output type is not their input's: they compute in the input's type.
template <typename T>
Compiled by_input_type(Compiler& c, const ProgramBlock& block) {
  const std::string& type = block.type();
  if (type == "Not") {
    const Operand<T> u = c.input<T>(block, 0);
    return {elementwise<bool>(c, block, [u](std::size_t i) { return !blocks::convert<bool>(u[i]); }), {}};
  }
  if (type == "Compare") {
    const Operand<T> u = c.input<T>(block, 0);
    const Operand<T> value = c.argument<T>(block, "value", 0);
    const blocks::CompareOperator op = compare_operator(block);
    return {elementwise<bool>(c, block, [u, value, op](std::size_t i) { return blocks::compare(op, u[i], value[i]); }),
            {}};
  }
  if (type == "Relational") {
    const Operand<T> u1 = c.input<T>(block, 0);
    const Operand<T> u2 = c.input<T>(block, 1);
    const blocks::CompareOperator op = compare_operator(block);
    return {elementwise<bool>(c, block, [u1, u2, op](std::size_t i) { return blocks::compare(op, u1[i], u2[i]); }), {}};
  }
  if (type == "EdgeDetect") {
    auto detector = std::make_shared<blocks::EdgeDetector<T>>();
    const Operand<T> u = c.input<T>(block, 0);
    const blocks::Edge edge = edge_of(block);
    bool* y = c.output<bool>(block, 0);
    return {{[detector, u, y, edge] { *y = detector->detect(edge, u[0]); }, {}},
            [detector] { detector->previous = T{0}; }};
  }
  if (type == "Convert") {
    const Operand<T> u = c.input<T>(block, 0);
    return with_type(c.type_out(block), [&](auto tag) -> Compiled {
      using To = decltype(tag);
      return {elementwise<To>(c, block, [u](std::size_t i) { return blocks::convert<To>(u[i]); }), {}};
    });
  }
  return {};
}

Compiled logic(Compiler& c, const ProgramBlock& block) {
  std::vector<std::function<bool(std::size_t)>> inputs;
  for (std::size_t k = 0; k < block.inputs.size(); ++k) {
    inputs.push_back(with_type(c.type_in(block, k), [&](auto tag) -> std::function<bool(std::size_t)> {
      using T = decltype(tag);
      const Operand<T> u = c.input<T>(block, k);
      return [u](std::size_t i) { return blocks::convert<bool>(u[i]); };
    }));
  }
  const blocks::LogicOperator op = logic_operator(block);
  const std::shared_ptr<bool[]> truths{new bool[inputs.size()]};
  return {elementwise<bool>(c, block,
                            [inputs, op, truths](std::size_t i) {
                              for (std::size_t k = 0; k < inputs.size(); ++k) truths.get()[k] = inputs[k](i);
                              return blocks::logic(op, std::span<const bool>{truths.get(), inputs.size()});
                            }),
          {}};
}

// Where rates meet: the writer's update phase takes the value, the reader's output phase hands it out (block
// comment in program.hpp; modes in block_semantics.hpp).
Compiled rate_transition(Compiler& c, const ProgramBlock& block) {
  const std::size_t bytes = size_of(c.type_out(block)) * c.elements_out(block);
  const Transfer transfer = transfer_of(c.program(), block);
  auto held = std::make_shared<std::vector<std::byte>>(bytes);
  auto produced = std::make_shared<std::vector<std::byte>>(bytes);
  auto countdown = std::make_shared<std::uint32_t>(0);
  std::byte* y = c.output<std::byte>(block, 0);
  const Operand<std::byte> u = c.input<std::byte>(block, 0);
  const std::byte* const* u_base = u.base;
  const std::size_t u_offset = u.offset;
  const auto release = [countdown, ratio = transfer.ratio] {
    const bool now = *countdown == 0;
    *countdown = now ? ratio - 1 : *countdown - 1;
    return now;
  };
  std::function<void()> output;
  std::function<void()> update;
  switch (transfer.kind) {
    case Transfer::Kind::fast_to_slow:
      output = [held, y] { std::memcpy(y, held->data(), held->size()); };
      update = [held, u_base, u_offset, release] {
        if (release()) std::memcpy(held->data(), *u_base + u_offset, held->size());
      };
      break;
    case Transfer::Kind::slow_to_fast:
      output = [held, produced, y, release] {
        if (release()) *held = *produced;
        std::memcpy(y, held->data(), held->size());
      };
      update = [produced, u_base, u_offset] { std::memcpy(produced->data(), *u_base + u_offset, produced->size()); };
      break;
    case Transfer::Kind::latest:
      output = [produced, y] { std::memcpy(y, produced->data(), produced->size()); };
      update = [produced, u_base, u_offset] { std::memcpy(produced->data(), *u_base + u_offset, produced->size()); };
      break;
  }
  // The initial value, in the output's type, in every buffer.
  auto initial = with_type(c.type_out(block), [&](auto tag) -> std::vector<std::byte> {
    using T = decltype(tag);
    const Operand<T> value = c.argument<T>(block, "initial", 0);
    std::vector<std::byte> result(bytes);
    for (std::size_t i = 0; i < result.size() / sizeof(T); ++i) {
      const T element = value[i];
      std::memcpy(result.data() + i * sizeof(T), &element, sizeof(T));
    }
    return result;
  });
  return {{output, update}, [held, produced, countdown, initial] {
            *held = initial;
            *produced = initial;
            *countdown = 0;
          }};
}

// Hardware blocks: outputs go to the plant element by element as doubles, inputs come from it.
Compiled hardware(Compiler& c, const ProgramBlock& block) {
  const std::string resource = hardware_resource(block);
  plant::Plant* plant = &c.plant();
  if (block.type() == "AdcStart") {  // starts a conversion of `count` samples
    const double count = block.argument("count")->value.elements.at(0);
    return {{[plant, resource, count] { plant->write(resource, {&count, 1}); }, {}}, {}};
  }
  // What the block writes (its inputs, element by element) and then reads back (its outputs): an SpiDma does both.
  std::vector<std::function<double(std::size_t)>> inputs;
  std::vector<std::size_t> input_counts;
  std::size_t written = 0;
  for (std::size_t k = 0; k < block.inputs.size(); ++k) {
    input_counts.push_back(c.elements_in(block, k));
    written += input_counts.back();
    // In the type the firmware's port takes (duet/hardware/hardware.hpp), so that the plant sees what it would get
    // from generated code: a PWM duty as a float, what SPI and IPC send as bytes.
    inputs.push_back(with_type(c.type_in(block, k), [&](auto tag) -> std::function<double(std::size_t)> {
      using T = decltype(tag);
      const Operand<T> u = c.input<T>(block, k);
      if (block.type() == "PwmOut")
        return [u](std::size_t i) { return static_cast<double>(blocks::convert<float>(u[i])); };
      if (block.type() == "SpiDma" || block.type() == "IpcSend") {
        return [u](std::size_t i) { return static_cast<double>(blocks::convert<std::uint8_t>(u[i])); };
      }
      return [u](std::size_t i) { return blocks::convert<double>(u[i]); };
    }));
  }
  std::vector<std::function<void(const double*)>> outputs;
  std::vector<std::size_t> output_offsets;  // where each output's values start in what the plant gives
  std::size_t read = 0;
  // An input capture reads [count, edge] whichever it uses, as the ports' capture_read() does.
  const bool capture = block.type() == "InputCapture";
  if (capture) read = 2;
  for (std::size_t k = 0; k < block.outputs.size(); ++k) {
    const std::size_t n = c.elements_out(block, k);
    output_offsets.push_back(capture ? (block.output_ports[k] == "edge" ? 1 : 0) : read);
    if (!capture) read += n;
    outputs.push_back(with_type(c.type_out(block, k), [&](auto tag) -> std::function<void(const double*)> {
      using T = decltype(tag);
      T* y = c.output<T>(block, k);
      return [y, n](const double* from) {
        for (std::size_t i = 0; i < n; ++i) y[i] = blocks::convert<T>(from[i]);
      };
    }));
  }
  auto to_plant = std::make_shared<std::vector<double>>(written);
  auto from_plant = std::make_shared<std::vector<double>>(read);
  return {{[plant, resource, inputs, input_counts, to_plant, outputs, output_offsets, from_plant] {
             if (!inputs.empty()) {
               std::size_t at = 0;
               for (std::size_t k = 0; k < inputs.size(); ++k) {
                 for (std::size_t i = 0; i < input_counts[k]; ++i) (*to_plant)[at++] = inputs[k](i);
               }
               plant->write(resource, *to_plant);
             }
             if (!outputs.empty()) {
               plant->read(resource, *from_plant);
               for (std::size_t k = 0; k < outputs.size(); ++k) outputs[k](from_plant->data() + output_offsets[k]);
             }
           },
           {}},
          {}};
}

// A Code block: its four structures as bytes laid out as generated code declares them (user_code.hpp), the inputs
// and parameters copied in, the function called, the outputs copied out; the state persists between calls.
Compiled code_block(Compiler& c, const ProgramBlock& block, CodeFunction function) {
  const CodeInterface interface = code_interface(c.program(), block);
  struct Copy {
    const std::byte* const* base;  // a signal's or a parameter's memory (through the page pointer)
    std::size_t offset;
    std::size_t to;
    std::size_t bytes;
  };
  struct Buffers {
    std::vector<double> in, out, state, parameters;  // doubles: aligned for every member
  };
  const auto words = [](std::size_t bytes) { return bytes / sizeof(double) + 1; };
  auto buffers = std::make_shared<Buffers>(
      Buffers{std::vector<double>(words(interface.inputs_size)), std::vector<double>(words(interface.outputs_size)),
              std::vector<double>(words(interface.state_size)), std::vector<double>(words(interface.parameters_size))});
  const auto field_named = [](const std::vector<Field>& fields, const std::string& name) {
    return *std::find_if(fields.begin(), fields.end(), [&name](const Field& field) { return field.name == name; });
  };
  std::vector<Copy> inputs;
  for (std::size_t k = 0; k < block.inputs.size(); ++k) {
    const Field field = field_named(interface.inputs, block.input_ports[k]);
    const Operand<std::byte> source = c.input<std::byte>(block, k);
    inputs.push_back({source.base, source.offset, field.offset, size_of(field.type) * field.count});
  }
  std::vector<Copy> parameters;
  for (const Field& field : interface.parameters) {
    parameters.push_back(with_type(field.type, [&](auto tag) -> Copy {
      using T = decltype(tag);
      const Operand<T> source = c.argument<T>(block, field.name, 0);
      return {source.base, source.offset, field.offset, sizeof(T) * field.count};
    }));
  }
  std::vector<std::pair<std::byte*, Field>> outputs;
  for (std::size_t k = 0; k < block.outputs.size(); ++k) {
    outputs.emplace_back(c.output<std::byte>(block, k), field_named(interface.outputs, block.output_ports[k]));
  }
  const auto bytes_of = [](std::vector<double>& buffer) { return reinterpret_cast<std::byte*>(buffer.data()); };
  std::vector<StateVariable> state = block.block->code->state;
  return {{[buffers, inputs, parameters, outputs, function, bytes_of] {
             std::fill(buffers->out.begin(), buffers->out.end(), 0.0);
             for (const Copy& copy : inputs) {
               std::memcpy(bytes_of(buffers->in) + copy.to, *copy.base + copy.offset, copy.bytes);
             }
             for (const Copy& copy : parameters) {
               std::memcpy(bytes_of(buffers->parameters) + copy.to, *copy.base + copy.offset, copy.bytes);
             }
             function(buffers->in.data(), buffers->out.data(), buffers->state.data(), buffers->parameters.data());
             for (const auto& [destination, field] : outputs) {
               std::memcpy(destination, bytes_of(buffers->out) + field.offset, size_of(field.type) * field.count);
             }
           },
           {}},
          [buffers, state, interface, bytes_of] {
            std::fill(buffers->state.begin(), buffers->state.end(), 0.0);
            for (std::size_t k = 0; k < state.size(); ++k) {
              with_type(state[k].type, [&](auto tag) {
                using T = decltype(tag);
                for (std::size_t i = 0; i < state[k].initial.elements.size(); ++i) {
                  const T value = blocks::convert<T>(state[k].initial.elements[i]);
                  std::memcpy(bytes_of(buffers->state) + interface.state[k].offset + i * sizeof(T), &value, sizeof(T));
                }
              });
            }
          }};
}

Compiled compile(Compiler& c, const ProgramBlock& block, const UserCodeLibrary* user_code, std::size_t index) {
  if (block.block->code) return code_block(c, block, user_code->function(index));
  const std::string& type = block.type();
  // A block whose outputs the model leaves unconnected computes nothing, as in generated code.
  if (block.outputs.empty() && hardware_resource(block).empty()) return {};
  if (type == "RateTransition") return rate_transition(c, block);
  if (type == "Logic") return logic(c, block);
  if (type == "BytePack" || type == "ByteUnpack") return bytes(c, block);
  if (!hardware_resource(block).empty()) return hardware(c, block);
  if (type == "Not" || type == "Compare" || type == "Relational" || type == "Convert" || type == "EdgeDetect") {
    return with_type(c.type_in(block), [&](auto tag) { return by_input_type<decltype(tag)>(c, block); });
  }
  return with_type(c.type_out(block), [&](auto tag) { return any_type<decltype(tag)>(c, block); });
}

// Runs a block's phase only while every enabling signal is true.
std::function<void()> guarded(const Compiler& c, const ProgramBlock& block, std::function<void()> phase) {
  if (!phase || block.enables.empty()) return phase;
  std::vector<std::function<bool()>> enables;
  for (const std::size_t signal : block.enables) {
    enables.push_back(with_type(c.program().signals[signal].type.type, [&](auto tag) -> std::function<bool()> {
      using T = decltype(tag);
      const Operand<T> value = c.signal<T>(signal);
      return [value] { return blocks::convert<bool>(value[0]); };
    }));
  }
  return [enables, phase] {
    for (const auto& enabled : enables) {
      if (!enabled()) return;
    }
    phase();
  };
}

}  // namespace

std::string hardware_resource(const ProgramBlock& block) {
  const auto text = [&block](const char* name) {
    const Argument* argument = block.argument(name);
    return argument == nullptr ? std::string{} : argument->text;
  };
  const std::string& type = block.type();
  if (type == "GpioIn" || type == "GpioOut") return "gpio:" + text("pin");
  if (type == "PwmOut") return "pwm:" + text("timer") + "/" + text("channel");
  if (type == "InputCapture") return "capture:" + text("timer") + "/" + text("channel");
  if (type == "SpiDma" || type == "SpiReceive") return "spi:" + text("spi");
  if (type == "Exti") return "exti:" + text("line");
  if (type == "AdcDma" || type == "AdcStart") return "adc:" + text("adc") + "/" + text("channel");
  if (type == "IpcSend" || type == "IpcReceive") return "ipc:" + text("channel");
  if (type == "PlantInput" || type == "PlantOutput") return text("resource");
  if (type == "Inport") return "inport:" + block.block->name;
  if (type == "Outport") return "outport:" + block.block->name;
  return {};
}

}  // namespace duet::model

namespace duet::model {

Interpreter::Interpreter(const Program& program) : program_(program), storage_(std::make_unique<Storage>()) {}
Interpreter::~Interpreter() = default;

Result<std::unique_ptr<Interpreter>> Interpreter::create(const Program& program, plant::Plant& plant,
                                                         const UserCodeLibrary* user_code) {
  for (std::size_t index = 0; index < program.blocks.size(); ++index) {
    if (program.blocks[index].block->code && (user_code == nullptr || user_code->function(index) == nullptr)) {
      return Failure{"block '" + program.blocks[index].path +
                     "' is a Code block: simulation needs its function compiled (UserCodeLibrary::build)"};
    }
  }
  std::unique_ptr<Interpreter> interpreter{new Interpreter{program}};
  Storage& storage = *interpreter->storage_;
  std::size_t end = 0;
  for (const ProgramSignal& signal : program.signals) {
    layout(storage.signal_offset, size_of(signal.type.type) * signal.type.elements(), size_of(signal.type.type), end);
  }
  storage.signals.assign(end / sizeof(double) + 1, 0.0);
  storage.signal_base = reinterpret_cast<std::byte*>(storage.signals.data());
  end = 0;
  for (const Parameter& parameter : program.model->parameters) {
    layout(storage.parameter_offset, size_of(parameter.type) * parameter.value.elements.size(), size_of(parameter.type),
           end);
  }
  storage.working.assign(end / sizeof(double) + 1, 0.0);
  storage.reference.assign(end / sizeof(double) + 1, 0.0);
  storage.working_base = reinterpret_cast<const std::byte*>(storage.working.data());
  storage.page = storage.working_base;
  for (std::size_t index = 0; index < program.model->parameters.size(); ++index) {
    const Parameter& parameter = program.model->parameters[index];
    for (std::size_t element = 0; element < parameter.value.elements.size(); ++element) {
      interpreter->set_parameter(index, element, parameter.value.elements[element]);
    }
  }
  storage.reference = storage.working;

  Compiler compiler{program, storage, plant};
  for (const ProgramBlock& block : program.blocks) {
    Compiled compiled = compile(compiler, block, user_code, static_cast<std::size_t>(&block - program.blocks.data()));
    interpreter->blocks_.push_back({guarded(compiler, block, std::move(compiled.phases.first)),
                                    guarded(compiler, block, std::move(compiled.phases.second))});
    if (compiled.reset) interpreter->resets_.push_back(std::move(compiled.reset));
  }
  return interpreter;
}

void Interpreter::initialize() {
  for (const auto& reset : resets_) reset();
  for (const std::size_t block : program_.initial_outputs) {
    if (blocks_[block].output) blocks_[block].output();
  }
}

void Interpreter::run_task(std::size_t task) {
  for (const std::size_t block : program_.tasks[task].outputs) {
    if (blocks_[block].output) blocks_[block].output();
  }
  for (const std::size_t block : program_.tasks[task].updates) {
    if (blocks_[block].update) blocks_[block].update();
  }
}

std::span<const std::byte> Interpreter::signal_bytes(std::size_t signal) const {
  const ProgramSignal& info = program_.signals[signal];
  const std::byte* base = info.parameter ? storage_->page + storage_->parameter_offset[*info.parameter]
                                         : storage_->signal_base + storage_->signal_offset[signal];
  return {base, size_of(info.type.type) * info.type.elements()};
}

double Interpreter::signal(std::size_t signal, std::size_t element) const {
  const std::span<const std::byte> bytes = signal_bytes(signal);
  return with_type(program_.signals[signal].type.type, [&](auto tag) {
    using T = decltype(tag);
    T value;
    std::memcpy(&value, bytes.data() + element * sizeof(T), sizeof(T));
    return blocks::convert<double>(value);
  });
}

void Interpreter::set_parameter(std::size_t parameter, std::size_t element, double value) {
  const auto& parameters = program_.model->parameters;
  if (parameter >= parameters.size() || element >= parameters[parameter].value.elements.size()) return;
  const DataType type = parameters[parameter].type;
  std::byte* at = reinterpret_cast<std::byte*>(storage_->working.data()) + storage_->parameter_offset[parameter];
  with_type(type, [&](auto tag) {
    using T = decltype(tag);
    const T converted = blocks::convert<T>(value);
    std::memcpy(at + element * sizeof(T), &converted, sizeof(T));
  });
}

void Interpreter::use_reference_page(bool reference) {
  storage_->page = reference ? reinterpret_cast<const std::byte*>(storage_->reference.data()) : storage_->working_base;
}

}  // namespace duet::model
