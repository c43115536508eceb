#include "duet/model/interpreter.hpp"

#include <cstring>
#include <deque>
#include <limits>

#include "block_semantics.hpp"
#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/convert.hpp"
#include "duet/blocks/logic.hpp"
#include "duet/blocks/matrix.hpp"
#include "duet/blocks/nonlinear.hpp"
#include "duet/blocks/state.hpp"
#include "duet/blocks/table.hpp"
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
      const std::string signs = sum_signs(block);
      const bool sum = type == "Sum";
      return {elementwise<T>(c, block,
                             [inputs, signs, sum](std::size_t i) {
                               if (!sum) {
                                 T y = inputs[0][i];
                                 for (std::size_t k = 1; k < inputs.size(); ++k) y = blocks::multiply(y, inputs[k][i]);
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
  if (type == "DiscretePid") {
    auto states = std::make_shared<std::vector<blocks::DiscretePid<T>>>(n);
    const std::array<Operand<T>, 6> gains{c.argument<T>(block, "p", 0),
                                          c.argument<T>(block, "i", 0),
                                          c.argument<T>(block, "d", 0),
                                          c.argument<T>(block, "n", pid_default_filter),
                                          c.argument<T>(block, "lower", -infinity),
                                          c.argument<T>(block, "upper", infinity)};
    const auto gains_of = [gains](std::size_t i) {
      return blocks::PidGains<T>{gains[0][i], gains[1][i], gains[2][i], gains[3][i], gains[4][i], gains[5][i]};
    };
    return {{[states, y, u, gains_of] {
               for (std::size_t i = 0; i < states->size(); ++i) y[i] = (*states)[i].output(u[i], gains_of(i));
             },
             [states, u, gains_of, period] {
               for (std::size_t i = 0; i < states->size(); ++i) (*states)[i].update(u[i], gains_of(i), period);
             }},
            [states] {
              for (auto& state : *states) state = {T{0}, T{0}};
            }};
  }
  return {};
}

// Blocks that compute in any element type, booleans too.
template <typename T>
Compiled any_type(Compiler& c, const ProgramBlock& block) {
  const std::string& type = block.type();
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
  // What the block writes (its inputs, element by element) and then reads back (its outputs): an SpiDma does both.
  std::vector<std::function<double(std::size_t)>> inputs;
  std::vector<std::size_t> input_counts;
  std::size_t written = 0;
  for (std::size_t k = 0; k < block.inputs.size(); ++k) {
    input_counts.push_back(c.elements_in(block, k));
    written += input_counts.back();
    inputs.push_back(with_type(c.type_in(block, k), [&](auto tag) -> std::function<double(std::size_t)> {
      using T = decltype(tag);
      const Operand<T> u = c.input<T>(block, k);
      return [u](std::size_t i) { return blocks::convert<double>(u[i]); };
    }));
  }
  std::vector<std::function<void(const double*)>> outputs;
  std::vector<std::size_t> output_counts;
  std::size_t read = 0;
  for (std::size_t k = 0; k < block.outputs.size(); ++k) {
    const std::size_t n = c.elements_out(block, k);
    output_counts.push_back(n);
    read += n;
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
  return {{[plant, resource, inputs, input_counts, to_plant, outputs, output_counts, from_plant] {
             if (!inputs.empty()) {
               std::size_t at = 0;
               for (std::size_t k = 0; k < inputs.size(); ++k) {
                 for (std::size_t i = 0; i < input_counts[k]; ++i) (*to_plant)[at++] = inputs[k](i);
               }
               plant->write(resource, *to_plant);
             }
             if (!outputs.empty()) {
               plant->read(resource, *from_plant);
               std::size_t at = 0;
               for (std::size_t k = 0; k < outputs.size(); ++k) {
                 outputs[k](from_plant->data() + at);
                 at += output_counts[k];
               }
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
  if (type == "Outport") return {};
  if (type == "RateTransition") return rate_transition(c, block);
  if (type == "Logic") return logic(c, block);
  if (!hardware_resource(block).empty()) return hardware(c, block);
  if (type == "Not" || type == "Compare" || type == "Convert" || type == "EdgeDetect") {
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
  if (type == "SpiDma") return "spi:" + text("spi");
  if (type == "Exti") return "exti:" + text("line");
  if (type == "AdcDma") return "adc:" + text("adc") + "/" + text("channel");
  if (type == "IpcSend" || type == "IpcReceive") return "ipc:" + text("channel");
  if (type == "PlantInput" || type == "PlantOutput") return text("resource");
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
