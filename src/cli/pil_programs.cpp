#include "pil_programs.hpp"

#include <unistd.h>

#include <array>
#include <charconv>
#include <initializer_list>

namespace duet::cli {
namespace {

// QEMU's option values are separated by commas; a comma inside a value is written twice.
std::string qemu_value(const std::string& text) {
  std::string escaped;
  for (const char character : text) {
    escaped += character;
    if (character == ',') escaped += ',';
  }
  return escaped;
}

// A UART as a unix socket QEMU listens on. wait=off: the firmware starts at once, whoever connects later (the
// bridge retries until it can); what the firmware sends before that is lost, as on a tty nobody reads.
std::string unix_socket_chardev(const std::string& id, const std::filesystem::path& path) {
  return "socket,id=" + id + ",path=" + qemu_value(path.string()) + ",server=on,wait=off";
}

}  // namespace

std::string shortest(double value) {
  std::array<char, 32> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} ? std::string(text.data(), end) : std::string{"nan"};
}

std::vector<std::string> qemu_command(const QemuSetup& setup) {
  std::string arguments =
      "enable=on,target=native,arg=" + qemu_value(std::filesystem::path{setup.firmware}.filename().string());
  arguments += ",arg=--link,arg=" + qemu_value(setup.folder.string());
  if (setup.duration_s) arguments += ",arg=--duration,arg=" + shortest(*setup.duration_s);
  std::vector<std::string> command{setup.qemu, "-machine", "mps2-an386", "-nographic",
                                   "-monitor", "none",     "-kernel",    setup.firmware};
  const auto add = [&command](std::initializer_list<std::string> words) { command.insert(command.end(), words); };
  // Deterministic: the emulated clock counts instructions (2^N ns each) and never waits for the host's.
  add({"-icount", "shift=" + std::to_string(setup.icount_shift) + ",align=off,sleep=off"});
  add({"-semihosting-config", arguments});
  // Successive -serial options are UART0, UART1, ...
  add({"-chardev", unix_socket_chardev("xcp", setup.folder / "xcp.sock"), "-serial", "chardev:xcp"});
  add({"-chardev", unix_socket_chardev("app", setup.folder / "app.sock"), "-serial", "chardev:app"});
  add({"-serial", "null", "-serial", "stdio"});
  return command;
}

std::vector<std::string> bridge_command(const BridgeSetup& setup) {
  std::vector<std::string> command{setup.bridge,
                                   "--channel",
                                   "unix:" + (setup.folder / "xcp.sock").string(),
                                   "--app-channel",
                                   "unix:" + (setup.folder / "app.sock").string(),
                                   "--listen",
                                   setup.xcp,
                                   "--websocket",
                                   setup.websocket};
  if (!setup.plant_control.empty()) command.insert(command.end(), {"--plant-control", setup.plant_control});
  return command;
}

std::string default_bridge(const std::filesystem::path& duet_program) {
  const std::filesystem::path beside = duet_program.parent_path().parent_path() / "bridge" / "duet-bridge";
  if (duet_program.is_absolute() && ::access(beside.c_str(), X_OK) == 0) return beside.string();
  return "duet-bridge";
}

}  // namespace duet::cli
