#pragma once
// How busy the rest of the machine kept its processors while a run went: the processor time of every process
// (Linux's /proc/stat) minus duet's own and its children's. A run whose emulator could not keep real time says why
// with it: on a machine whose other programs keep both cores busy, QEMU gets the processor late.

#include <optional>
#include <string_view>

namespace duet::cli {

// The busy time of every processor together since boot, in seconds, from the text of /proc/stat: its "cpu" line's
// user, nice, system, irq, softirq and steal (a virtual machine's processor taken by its host is not ours either);
// none when the text has no such line. `ticks_per_second`: the kernel's USER_HZ (sysconf(_SC_CLK_TCK)).
[[nodiscard]] std::optional<double> busy_seconds_from_proc_stat(std::string_view text, long ticks_per_second);

struct MachineLoad {
  int processors = 0;
  double others_busy = 0;  // processors the rest of the machine kept busy, on average (0 to `processors`)
};

// Measures from its making to finish(): the machine's busy time and this process's and its waited-for children's.
class MachineLoadMeter {
 public:
  MachineLoadMeter();
  // Call after the children were waited for (their time counts only then). None when /proc/stat cannot be read.
  [[nodiscard]] std::optional<MachineLoad> finish(double wall_s) const;

 private:
  std::optional<double> machine_busy_s_;
  double own_s_ = 0;
};

}  // namespace duet::cli
