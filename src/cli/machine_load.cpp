#include "machine_load.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace duet::cli {
namespace {

std::optional<double> machine_busy_seconds() {
  std::ifstream file{"/proc/stat"};
  const std::string text{std::istreambuf_iterator<char>{file}, std::istreambuf_iterator<char>{}};
  return busy_seconds_from_proc_stat(text, ::sysconf(_SC_CLK_TCK));
}

double seconds(const timeval& time) {
  return static_cast<double>(time.tv_sec) + static_cast<double>(time.tv_usec) * 1e-6;
}

// User and system time of this process and of its children that were waited for.
double own_seconds() {
  double total = 0;
  for (const int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage usage{};
    if (::getrusage(who, &usage) == 0) total += seconds(usage.ru_utime) + seconds(usage.ru_stime);
  }
  return total;
}

}  // namespace

std::optional<double> busy_seconds_from_proc_stat(std::string_view text, long ticks_per_second) {
  std::istringstream lines{std::string{text}};
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words{line};
    std::string label;
    // user nice system idle iowait irq softirq steal (guest time is inside user and nice)
    std::array<double, 8> fields{};
    if (!(words >> label) || label != "cpu") continue;
    for (double& field : fields) {
      if (!(words >> field)) return std::nullopt;
    }
    if (ticks_per_second <= 0) return std::nullopt;
    const double busy = fields[0] + fields[1] + fields[2] + fields[5] + fields[6] + fields[7];
    return busy / static_cast<double>(ticks_per_second);
  }
  return std::nullopt;
}

MachineLoadMeter::MachineLoadMeter() : machine_busy_s_(machine_busy_seconds()), own_s_(own_seconds()) {}

std::optional<MachineLoad> MachineLoadMeter::finish(double wall_s) const {
  const std::optional<double> machine_busy_s = machine_busy_seconds();
  if (!machine_busy_s_ || !machine_busy_s || wall_s <= 0) return std::nullopt;
  const double others_s = (*machine_busy_s - *machine_busy_s_) - (own_seconds() - own_s_);
  const int processors = static_cast<int>(std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN)));
  return MachineLoad{processors, std::clamp(others_s / wall_s, 0.0, static_cast<double>(processors))};
}

}  // namespace duet::cli
