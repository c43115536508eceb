// libFuzzer target: arbitrary bytes as an MDF 4 file. The reader opens them and, if that succeeds, decodes every
// record of every group with its physical value and time, then summarises and exports them as `duet mdf` does (the
// export merges the groups by time, whatever the times are): an error or values, never a crash or a hang.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <vector>

#include "duet/mdf4/csv_export.hpp"
#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/summary.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto reader = duet::mdf4::Reader::from_bytes(std::vector<std::uint8_t>(data, data + size), "fuzz.mf4");
  if (!reader) return 0;
  const duet::mdf4::FileInfo& info = reader.value().info();
  for (std::size_t group = 0; group < info.groups.size(); ++group) {
    const std::size_t channels = info.groups[group].channels.size();
    (void)reader.value().for_each_record(group, [&](const duet::mdf4::Record& record) {
      (void)record.time();
      for (std::size_t channel = 0; channel < channels; ++channel) {
        (void)record.valid(channel);
        (void)record.physical(channel);
      }
    });
  }
  (void)duet::mdf4::summarise(reader.value());
  std::ostringstream csv;
  (void)duet::mdf4::export_csv(reader.value(), {}, csv);
  return 0;
}
