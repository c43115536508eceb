#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "command_line.hpp"

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    return static_cast<int>(duet::cli::run_command_line(arguments, {std::cout, std::cerr}));
  } catch (const std::exception& error) {  // a bug or an exhausted machine: say so instead of aborting
    std::cerr << "duet: internal error: " << error.what() << '\n';
    return static_cast<int>(duet::cli::ExitCode::failure);
  }
}
