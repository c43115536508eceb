#include "duet/mdf4/csv_export.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <optional>

#include "duet/mdf4/summary.hpp"

namespace duet::mdf4 {
namespace {

struct Column {
  std::size_t group = 0;
  std::size_t channel = 0;
  std::string header;
};

template <typename T>
void write_number(std::ostream& out, T value) {
  char text[40];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.write(text, end - text);
}

void write_text(std::ostream& out, const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) {
    out << text;
    return;
  }
  out << '"';
  for (const char character : text) out << (character == '"' ? "\"\"" : std::string{character});
  out << '"';
}

// Integers as integers, floats in the fewest digits that read back to the same value.
void write_physical(std::ostream& out, const Physical& value) {
  std::visit(
      [&](const auto& held) {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, std::string>) {
          write_text(out, held);
        } else if constexpr (std::is_same_v<T, double>) {
          write_number(out, held);
        } else {
          std::visit([&](auto number) { write_number(out, number); }, held);
        }
      },
      value);
}

// How many groups have a channel of each name: a name in several needs its group to be unambiguous.
std::map<std::string, std::size_t> name_counts(const FileInfo& info) {
  std::map<std::string, std::size_t> counts;
  for (const GroupInfo& group : info.groups) {
    std::map<std::string, bool> seen;
    for (const ChannelInfo& channel : group.channels) {
      if (!seen[channel.name]) ++counts[channel.name];
      seen[channel.name] = true;
    }
  }
  return counts;
}

Result<std::vector<Column>> choose_columns(const FileInfo& info, const std::vector<std::string>& names,
                                           CsvExport& summary) {
  const std::map<std::string, std::size_t> counts = name_counts(info);
  const auto header_of = [&](std::size_t group, const ChannelInfo& channel) {
    return counts.at(channel.name) > 1 ? std::to_string(group) + ":" + channel.name : channel.name;
  };
  std::vector<Column> columns;
  if (names.empty()) {
    for (std::size_t group = 0; group < info.groups.size(); ++group) {
      for (std::size_t channel = 0; channel < info.groups[group].channels.size(); ++channel) {
        const ChannelInfo& found = info.groups[group].channels[channel];
        if (found.role != ChannelInfo::Role::value) continue;
        if (!found.decoded) {
          summary.not_decoded.push_back(header_of(group, found) + " (" + type_text(found) + ")");
          continue;
        }
        columns.push_back({group, channel, header_of(group, found)});
      }
    }
    return columns;
  }
  for (const std::string& name : names) {
    std::optional<std::size_t> only_group;
    std::string channel_name = name;
    if (const std::size_t colon = name.find(':'); colon != std::string::npos) {
      std::size_t group = 0;
      const auto [end, error] = std::from_chars(name.data(), name.data() + colon, group);
      if (error == std::errc{} && end == name.data() + colon) {
        only_group = group;
        channel_name = name.substr(colon + 1);
      }
    }
    std::vector<Column> found;
    for (std::size_t group = 0; group < info.groups.size(); ++group) {
      if (only_group && group != *only_group) continue;
      for (std::size_t channel = 0; channel < info.groups[group].channels.size(); ++channel) {
        if (info.groups[group].channels[channel].name == channel_name)
          found.push_back({group, channel, header_of(group, info.groups[group].channels[channel])});
      }
    }
    if (found.empty()) return Failure{"no channel '" + name + "' in the file (duet mdf info lists them)"};
    if (found.size() > 1) {
      std::string groups;
      for (const Column& column : found) groups += (groups.empty() ? "" : ", ") + std::to_string(column.group);
      std::string message = "channel '" + name + "' is in groups ";
      message += groups;
      message += "; name it as GROUP:";
      message += channel_name;
      return Failure{message};
    }
    const ChannelInfo& channel = info.groups[found[0].group].channels[found[0].channel];
    if (!channel.decoded)
      return Failure{"channel '" + name + "' is " + type_text(channel) + "; duet exports numbers and texts"};
    columns.push_back(found[0]);
  }
  return columns;
}

double time_of(const GroupInfo& group, const Record& record) {
  return group.master ? record.time() : static_cast<double>(record.index());
}

}  // namespace

Result<CsvExport> export_csv(const Reader& reader, const std::vector<std::string>& channels, std::ostream& out) {
  const FileInfo& info = reader.info();
  CsvExport summary;
  auto chosen = choose_columns(info, channels, summary);
  if (!chosen) return Failure{chosen.error()};
  const std::vector<Column>& columns = chosen.value();
  summary.columns = columns.size();

  // The groups the columns come from, each read by its own cursor.
  std::vector<std::size_t> groups;
  for (const Column& column : columns) {
    if (std::find(groups.begin(), groups.end(), column.group) == groups.end()) groups.push_back(column.group);
  }
  bool seconds = !groups.empty();
  for (const std::size_t group : groups) {
    const GroupInfo& found = info.groups[group];
    seconds = seconds && found.master && found.channels[*found.master].unit == "s";
  }
  out << (seconds ? "time_s" : "time");
  for (const Column& column : columns) {
    out << ',';
    write_text(out, column.header);
  }
  out << '\n';

  std::vector<RecordCursor> cursors;
  std::vector<std::optional<Record>> current;
  for (const std::size_t group : groups) {
    cursors.push_back(reader.records(group));
    current.push_back(cursors.back().next());
  }
  // Each row: the earliest time among the groups' next records (a NaN time first, so that it cannot stall the merge),
  // with every group whose next record has that time.
  while (true) {
    std::optional<std::size_t> earliest;
    for (std::size_t index = 0; index < groups.size(); ++index) {
      if (!current[index]) continue;
      const double time = time_of(info.groups[groups[index]], *current[index]);
      if (!earliest || std::isnan(time) || time < time_of(info.groups[groups[*earliest]], *current[*earliest]))
        earliest = index;
      if (std::isnan(time)) break;
    }
    if (!earliest) break;
    const double time = time_of(info.groups[groups[*earliest]], *current[*earliest]);
    std::vector<bool> in_row(groups.size(), false);
    in_row[*earliest] = true;
    for (std::size_t index = 0; index < groups.size(); ++index) {
      if (current[index] && time_of(info.groups[groups[index]], *current[index]) == time) in_row[index] = true;
    }
    write_number(out, time);
    for (const Column& column : columns) {
      out << ',';
      const std::size_t index =
          static_cast<std::size_t>(std::find(groups.begin(), groups.end(), column.group) - groups.begin());
      if (in_row[index] && current[index]->valid(column.channel))
        write_physical(out, current[index]->physical(column.channel));
    }
    out << '\n';
    ++summary.rows;
    for (std::size_t index = 0; index < groups.size(); ++index) {
      if (in_row[index]) current[index] = cursors[index].next();
    }
  }
  for (const RecordCursor& cursor : cursors) {
    if (!cursor.error().empty()) return Failure{cursor.error()};
  }
  if (!out) return Failure{"cannot write the CSV"};
  return summary;
}

}  // namespace duet::mdf4
