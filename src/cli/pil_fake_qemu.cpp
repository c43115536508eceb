// A stand-in for qemu-system-arm in `duet pil`'s tests (--qemu): takes QEMU's command line as duet pil writes it,
// and plays a firmware that opens the plant's pipes (semihosting "--link FOLDER", as the real firmware does), ticks
// at 1 ms in lock-step for the semihosting "--duration S" (or until a signal) and speaks the console protocol on
// standard output. The "firmware image" (-kernel FILE) is a few KEY=VALUE lines that say how to misbehave:
//   exit_code=N   the exit code at the end (default 0)
//   connect=0     end at once without connecting to the plant
//   garbage=1     send a frame of no known kind after HELLO
//   hang=1        connect, then say nothing and wait for a signal (what ends it must come from outside)
//   cut_line=1    leave half a console line unfinished, as the real firmware does when a signal stops it mid-line
#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "duet/link/remote_plant.hpp"
#include "duet/link/stream.hpp"

namespace {

// The value after `key=` in a comma-separated QEMU option value, or empty.
std::string option_value(std::string_view option, std::string_view key) {
  const std::string wanted = std::string{key} + "=";
  for (std::size_t start = 0; start <= option.size();) {
    const std::size_t end = std::min(option.find(',', start), option.size());
    const std::string_view item = option.substr(start, end - start);
    if (item.starts_with(wanted)) return std::string{item.substr(wanted.size())};
    start = end + 1;
  }
  return {};
}

struct Setup {
  std::map<std::string, std::string> behaviour;  // from the "image"
  std::string link_folder;
  double duration_s = -1;  // none: until a signal
};

Setup read_command_line(int argc, char** argv) {
  Setup setup;
  for (int k = 1; k + 1 < argc; ++k) {
    const std::string_view option = argv[k];
    const std::string value = argv[k + 1];
    if (option == "-kernel") {
      std::ifstream image{value};
      for (std::string line; std::getline(image, line);) {
        const std::size_t equals = line.find('=');
        if (equals != std::string::npos) setup.behaviour[line.substr(0, equals)] = line.substr(equals + 1);
      }
    } else if (option == "-semihosting-config") {
      const std::size_t link = value.find("arg=--link,arg=");
      if (link != std::string::npos) setup.link_folder = option_value(value.substr(link + 11), "arg");
      const std::size_t found = value.find("arg=--duration,arg=");
      if (found != std::string::npos) setup.duration_s = std::stod(value.substr(found + 19));
    }
  }
  return setup;
}

void report(std::uint64_t ticks) {
  std::cout << "duet-status time_s=" << static_cast<double>(ticks) * 0.001 << " ticks=" << ticks
            << " busy_ppm=250000 overruns=0\n"
            << "duet-task index=0 name=step_rate_1 activations=" << ticks
            << " overruns=0 min_cycles=100 mean_cycles=150 max_cycles=200\n"
            << std::flush;
}

}  // namespace

int main(int argc, char** argv) {
  const Setup setup = read_command_line(argc, argv);
  const auto said = [&setup](const std::string& key, const std::string& otherwise) {
    const auto found = setup.behaviour.find(key);
    return found == setup.behaviour.end() ? otherwise : found->second;
  };
  const int exit_code = std::stoi(said("exit_code", "0"));
  std::cout << "fake-qemu pid=" << ::getpid() << std::endl;
  if (said("connect", "1") == "0") return exit_code;

  // As the firmware does: the pipe to the plant for writing, then the one from it for reading.
  const int to_plant = ::open((setup.link_folder + "/to_plant").c_str(), O_WRONLY | O_CLOEXEC);
  const int from_plant = ::open((setup.link_folder + "/from_plant").c_str(), O_RDONLY | O_CLOEXEC);
  if (to_plant < 0 || from_plant < 0) {
    std::cerr << "fake-qemu: cannot open the plant's pipes in " << setup.link_folder << '\n';
    return 1;
  }
  auto stream = std::make_unique<duet::link::FdStream>(from_plant, to_plant, duet::link::default_timeout);
  if (said("hang", "0") == "1") {
    ::pause();
    return exit_code;
  }
  if (said("garbage", "0") == "1") {
    const std::vector<std::uint8_t> hello{0x01, 6, 0, 2, 0, 0x40, 0x42, 0x0F, 0x00};
    const std::vector<std::uint8_t> nonsense{0x42, 0, 0};
    (void)stream->write_all(hello);
    (void)stream->write_all(nonsense);
    ::pause();  // the plant gives up on us; duet stops us
    return exit_code;
  }
  auto plant = duet::link::RemotePlant::connect(std::move(stream), {duet::link::LinkMode::lock_step, 1'000'000});
  if (!plant) {
    std::cerr << "fake-qemu: " << plant.error() << '\n';
    return 1;
  }
  const auto last_tick = static_cast<std::uint64_t>(setup.duration_s * 1000 + 0.5);
  const bool cut_line = said("cut_line", "0") == "1";
  if (cut_line) std::cout << "duet-task i" << std::flush;  // and no more reports, which would run on from it
  std::uint64_t tick = 1;
  for (; setup.duration_s < 0 || tick <= last_tick; ++tick) {
    plant.value()->advance(static_cast<double>(tick) * 0.001, [](std::string_view) {});
    if (!plant.value()->ok()) {
      std::cout << "error: the plant link failed: " << plant.value()->error() << std::endl;
      return 2;
    }
    if (tick % 100 == 0 && !cut_line) report(tick);
  }
  (void)plant.value()->close();
  std::cout << "duet-end reason=final_tick ticks=" << tick - 1 << " overruns=0" << std::endl;
  return exit_code;
}
