// libFuzzer target: arbitrary bytes as an MDF 4 file. The reader opens them and, if that succeeds, decodes every
// record of every group with its physical value and time: it must give an error or values, never crash or hang.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "duet/mdf4/reader.hpp"

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
  return 0;
}
