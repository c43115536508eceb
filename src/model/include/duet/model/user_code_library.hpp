#pragma once
// Simulation of Code blocks (docs/MODELS.md, "User code"): their C++ functions, compiled with the PC's compiler into a
// shared library and loaded, so that `duet sim` runs the very functions the firmware runs. The interpreter calls
// each through a plain function taking its four structures as bytes.

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "duet/model/program.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

using CodeFunction = void (*)(const void* inputs, void* outputs, void* state, const void* parameters);

class UserCodeLibrary {
 public:
  // Compiles the program's Code blocks with $CXX (default c++), their headers found in the model's folder. Fails with
  // the compiler's messages. A program without Code blocks needs no library.
  static Result<std::unique_ptr<UserCodeLibrary>> build(const Program& program);

  UserCodeLibrary(const UserCodeLibrary&) = delete;
  UserCodeLibrary& operator=(const UserCodeLibrary&) = delete;
  ~UserCodeLibrary();

  // The function of the Code block with that index in the program; nullptr for another block.
  [[nodiscard]] CodeFunction function(std::size_t block) const;

 private:
  UserCodeLibrary() = default;

  void* handle_ = nullptr;
  std::filesystem::path folder_;  // where it was built; removed with it
  std::map<std::size_t, CodeFunction> functions_;
};

}  // namespace duet::model
