#include "duet/mdf4/summary.hpp"

#include <ctime>
#include <sstream>

#include "duet/support/number_text.hpp"
#include "format.hpp"

namespace duet::mdf4 {
namespace {

std::string utc_text(std::uint64_t nanoseconds) {
  const auto seconds = static_cast<std::time_t>(nanoseconds / 1'000'000'000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[64];
  const std::size_t size = std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &utc);
  char fraction[16];
  std::snprintf(fraction, sizeof fraction, ".%09llu", static_cast<unsigned long long>(nanoseconds % 1'000'000'000));
  return std::string{text, size} + fraction + " UTC";
}

std::string unfinalised_text(std::uint16_t flags) {
  std::string text;
  const auto add = [&](std::uint16_t flag, const char* what) {
    if ((flags & flag) != 0) text += std::string{text.empty() ? "" : ", "} + what;
  };
  add(format::id::cycle_counts_flag, "sample counts");
  add(format::id::last_dt_length_flag, "the last data block's length");
  add(format::id::last_dl_flag, "the last data lists");
  return text.empty() ? "" : " (recovered: " + text + ")";
}

std::string conversion_text(const Conversion& conversion) {
  switch (conversion.kind) {
    case Conversion::Kind::identity: return "";
    case Conversion::Kind::linear:
      return ", physical = " + shortest_text(conversion.factor) + " * stored + " + shortest_text(conversion.offset);
    case Conversion::Kind::value_to_text: return ", " + std::to_string(conversion.texts.size()) + " value texts";
    case Conversion::Kind::unsupported:
      return ", conversion type " + std::to_string(conversion.cc_type) + " (not applied)";
  }
  return "";
}

}  // namespace

std::string type_text(const ChannelInfo& channel) {
  if (channel.role == ChannelInfo::Role::virtual_master || (channel.decoded && channel.bit_count == 0))
    return "record index";
  using namespace format::data_type;
  const std::uint8_t type = channel.data_type;
  const char* const kinds[] = {"u", "u", "i", "i", "f", "f"};
  if (!channel.decoded) {
    const char* const others[] = {"string", "string", "string", "string", "byte array", "MIME sample", "MIME stream"};
    return std::string{type >= 6 && type <= 12 ? others[type - 6] : "data type " + std::to_string(type)} +
           " (not decoded)";
  }
  std::string text = kinds[type] + std::to_string(channel.bit_count);
  if (channel.bit_offset != 0) text += " at bit " + std::to_string(channel.bit_offset);
  if (type == unsigned_be || type == signed_be || type == float_be) text += " big-endian";
  return text;
}

Result<std::string> summarise(const Reader& reader) {
  const FileInfo& info = reader.info();
  std::ostringstream out;
  out << "MDF " << info.version << ", program \"" << info.program << "\", "
      << (info.finalised ? "finalised" : "not finalised" + unfinalised_text(info.unfinalised_flags)) << '\n';
  for (const std::string& tool : info.history) out << "history: " << tool << '\n';
  out << "start: " << utc_text(info.start_time_ns) << '\n';
  for (std::size_t index = 0; index < info.groups.size(); ++index) {
    const GroupInfo& group = info.groups[index];
    out << "group " << index << " \"" << group.name << "\": " << group.samples
        << (group.samples == 1 ? " sample" : " samples");
    auto span = reader.time_span(index);
    if (!span) return Failure{span.error()};
    if (span.value()) {
      const std::string unit = group.channels[*group.master].unit;
      out << ", " << shortest_text(span.value()->first) << " to " << shortest_text(span.value()->second)
          << (unit.empty() ? "" : " " + unit);
    }
    if (!group.comment.empty()) out << " (" << group.comment << ')';
    out << '\n';
    for (const ChannelInfo& channel : group.channels) {
      out << "  " << channel.name << ": " << type_text(channel);
      if (!channel.unit.empty()) out << " [" << channel.unit << ']';
      if (channel.role != ChannelInfo::Role::value) out << ", master";
      out << conversion_text(channel.conversion);
      if (!channel.comment.empty()) out << " (" << channel.comment << ')';
      out << '\n';
    }
  }
  return out.str();
}

}  // namespace duet::mdf4
