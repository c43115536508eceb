// duet-bridge: relays XCP between the real-time core's channel and TCP on the Linux side.
// A placeholder until the relay lands (issue #5); it already proves the armhf build and its tooling.
#include <CLI/CLI.hpp>
#include <sys/utsname.h>

#include <exception>
#include <iostream>
#include <string>

#include "duet/version.hpp"

namespace {

// The machine the program runs on as the kernel reports it: "armv7l" on the board and under qemu-arm.
std::string machine() {
  utsname name{};
  return uname(&name) == 0 ? std::string{name.machine} : std::string{"unknown"};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    CLI::App app{"duet-bridge: relays XCP between the real-time core and TCP (arrives with issue #5)", "duet-bridge"};
    app.set_version_flag("--version", "duet-bridge " + std::string{duet::version} + " on " + machine());
    CLI11_PARSE(app, argc, argv);
    std::cerr << "duet-bridge: the relay is not implemented yet (planned in issue #5)\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "duet-bridge: internal error: " << error.what() << '\n';
    return 1;
  }
}
