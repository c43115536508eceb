#pragma once
// Runs a Program on the PC without generating code: every block becomes a pair of small functions (output, update)
// over typed storage, calling the same duet::blocks functions the generated code calls, in the same order, so that
// both compute bit-identical values. Hardware blocks talk to a plant (duet/plant/plant.hpp).
//
// Parameters live in two pages like the generated calibration segment: the working page, which set_parameter()
// writes, and the reference page, the model's values. The blocks read the page selected by use_reference_page().

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "duet/model/program.hpp"
#include "duet/model/user_code_library.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

class Interpreter {
 public:
  // `program`, `plant` and `user_code` must outlive the interpreter. A program with Code blocks needs their compiled
  // functions (UserCodeLibrary::build).
  static Result<std::unique_ptr<Interpreter>> create(const Program& program, plant::Plant& plant,
                                                     const UserCodeLibrary* user_code = nullptr);

  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;
  ~Interpreter();

  // Resets the state to its initial values and computes the constant blocks.
  void initialize();
  // One activation of a task: its blocks' outputs in execution order, then their updates.
  void run_task(std::size_t task);

  // A signal's element as a double (booleans 0 or 1).
  [[nodiscard]] double signal(std::size_t signal, std::size_t element = 0) const;
  // A signal's bytes as the generated code would hold them.
  [[nodiscard]] std::span<const std::byte> signal_bytes(std::size_t signal) const;

  // Writes one element of a tunable parameter on the working page, converted to its type (saturated like a Convert
  // block). A parameter or element the model does not have is ignored.
  void set_parameter(std::size_t parameter, std::size_t element, double value);
  void use_reference_page(bool reference);

  struct Storage;  // typed memory of signals, parameters and literals

 private:
  explicit Interpreter(const Program& program);

  struct Phases {
    std::function<void()> output;
    std::function<void()> update;
  };

  const Program& program_;
  std::unique_ptr<Storage> storage_;
  std::vector<Phases> blocks_;
  std::vector<std::function<void()>> resets_;  // initial state of each block that has state
};

// The resource a hardware block touches, as plants name it: "gpio:LED0", "pwm:TIM1/1", ...; empty for other blocks.
[[nodiscard]] std::string hardware_resource(const ProgramBlock& block);

}  // namespace duet::model
