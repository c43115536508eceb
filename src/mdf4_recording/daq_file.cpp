#include "duet/mdf4_recording/daq_file.hpp"

#include <sstream>

#include "duet/mdf4_recording/a2l_channels.hpp"

namespace duet::mdf4_recording {
namespace {

std::string describe(const xcp::host::EventInfo& event) {
  std::ostringstream text;
  text << "XCP event " << event.channel;
  if (event.period_s() > 0) {
    text << ", every " << event.period_s() << " s";
  } else {
    text << ", not periodic";
  }
  return text.str();
}

}  // namespace

DaqFile::DaqFile(mdf4::Writer writer, std::vector<DaqGroup> groups, std::size_t groups_before)
    : writer_(std::move(writer)), groups_(std::move(groups)), groups_before_(groups_before) {
  for (const DaqGroup& group : groups_) {
    std::size_t values = 0;
    for (const xcp::host::Variable& variable : group.variables) values += variable.count;
    values_per_sample_.push_back(values);
  }
}

Result<DaqFile> DaqFile::create(const std::filesystem::path& path, std::vector<DaqGroup> groups,
                                const std::string& comment, std::int64_t start_time_ns,
                                std::vector<mdf4::GroupSpec> groups_before) {
  const std::size_t before = groups_before.size();
  mdf4::FileSpec spec{.groups = std::move(groups_before), .start_time_ns = start_time_ns, .comment = comment};
  for (const DaqGroup& group : groups) {
    mdf4::GroupSpec described{.name = group.event.name, .comment = describe(group.event), .channels = {}};
    for (const xcp::host::Variable& variable : group.variables) described.channels.push_back(channel(variable));
    spec.groups.push_back(std::move(described));
  }
  auto writer = mdf4::Writer::create(path, spec);
  if (!writer) return Failure{writer.error()};
  return DaqFile{std::move(writer).value(), std::move(groups), before};
}

Status DaqFile::append(std::size_t list, double time_s, std::optional<std::span<const std::uint8_t>> bytes) {
  values_.clear();
  if (!bytes) {
    values_.resize(values_per_sample_.at(list), std::monostate{});
  } else {
    std::size_t at = 0;
    for (const xcp::host::Variable& variable : groups_.at(list).variables) {
      const std::size_t size = xcp::host::size_of(variable.type) * variable.count;
      if (at + size > bytes->size()) break;  // the writer refuses the short sample, naming the group
      append_raw_values(variable, bytes->subspan(at, size), values_);
      at += size;
    }
  }
  return writer_.append(groups_before_ + list, time_s, values_);
}

Status DaqFile::append_before(std::size_t group, double time_s, std::span<const mdf4::Value> values) {
  if (group >= groups_before_) return Failure{"no group " + std::to_string(group) + " before the DAQ lists"};
  return writer_.append(group, time_s, values);
}

}  // namespace duet::mdf4_recording
