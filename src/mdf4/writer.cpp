#include "duet/mdf4/writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "bytes.hpp"
#include "duet/version.hpp"
#include "file_description.hpp"
#include "format.hpp"

namespace duet::mdf4 {
namespace {

constexpr std::uint64_t dl_size = 56;  // one data block: header, next and one link, flags and count, one offset

const char* type_name(std::size_t value_index) {
  constexpr const char* names[] = {"missing", "bool", "u8",  "u16", "u32", "u64",
                                   "i8",      "i16",  "i32", "i64", "f32", "f64"};
  return names[value_index];
}

// A group's records as they arrive: buffered behind room for their data block's header, appended as a fragment.
struct GroupState {
  std::string name;
  DescribedGroup described;
  std::vector<std::string> channel_names;
  ByteBuffer pending;  // a DT header's room, then the buffered records
  std::uint64_t records_written = 0;
  std::uint64_t records_pending = 0;
  std::uint64_t data_bytes_written = 0;
  std::uint64_t last_list = 0;  // the last DL of the group's chain; 0: none yet (the DG's data link is NIL)
  double last_time = -std::numeric_limits<double>::infinity();
};

void start_pending(ByteBuffer& pending) {
  pending.bytes().clear();
  pending.append_zeros(format::header_size);
}

std::vector<std::string> channel_names(const GroupSpec& spec) {
  std::vector<std::string> names;
  for (const ChannelSpec& channel : spec.channels) {
    for (std::size_t element = 0; element < channel.elements; ++element)
      names.push_back(channel.elements == 1 ? channel.name : channel.name + "[" + std::to_string(element) + "]");
  }
  return names;
}

std::string check_spec(const FileSpec& spec) {
  for (std::size_t group = 0; group < spec.groups.size(); ++group) {
    for (const ChannelSpec& channel : spec.groups[group].channels) {
      const std::string where = "group " + std::to_string(group) + " ('" + spec.groups[group].name + "')";
      if (channel.name.empty()) return where + ": a channel has no name";
      if (channel.elements == 0) return where + ": channel '" + channel.name + "' has no elements";
      if (channel.conversion &&
          !(std::isfinite(channel.conversion->factor) && std::isfinite(channel.conversion->offset)))
        return where + ": channel '" + channel.name + "' has a conversion that is not finite";
    }
  }
  return {};
}

}  // namespace

struct Writer::State {
  std::filesystem::path path;
  int file = -1;
  WriterOptions options;
  std::vector<GroupState> groups;
  std::uint64_t end = 0;  // the file's size, always a multiple of 8
  bool finalised = false;
  std::string failure;  // the first failure to write: nothing more is written after it

  ~State() {
    if (file >= 0) ::close(file);
  }

  Status fail(const std::string& what) {
    if (failure.empty()) failure = path.string() + ": cannot " + what + ": " + std::strerror(errno);
    return Failure{failure};
  }

  Status write_at(std::uint64_t offset, const std::uint8_t* bytes, std::size_t size) {
    while (size > 0) {
      const ssize_t written = ::pwrite(file, bytes, size, static_cast<off_t>(offset));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) return fail("write");
      bytes += written;
      offset += static_cast<std::uint64_t>(written);
      size -= static_cast<std::size_t>(written);
    }
    return done();
  }

  template <typename T>
  Status patch(std::uint64_t at, T value) {
    std::uint8_t bytes[sizeof value];
    store(bytes, value);
    return write_at(at, bytes, sizeof value);
  }

  // The pending records as a DT block, followed by a DL that lists it, linked last into the group's chain: the link
  // is written after the blocks, so a crash in between leaves the chain as it was.
  Status write_fragment(GroupState& group) {
    if (group.records_pending == 0) return done();
    ByteBuffer& block = group.pending;
    const std::uint64_t data_size = block.size() - format::header_size;
    const std::uint64_t dt_offset = end;
    std::copy_n("##DT", 4, block.bytes().begin());
    block.put<std::uint64_t>(format::length_field, format::header_size + data_size);
    block.align(format::alignment);
    const std::uint64_t list_offset = end + block.size();
    block.append_text("##DL");
    block.append<std::uint32_t>(0);
    block.append<std::uint64_t>(dl_size);
    block.append<std::uint64_t>(2);
    block.append<std::uint64_t>(0);  // no next list yet
    block.append<std::uint64_t>(dt_offset);
    block.append<std::uint8_t>(0);  // offsets, not one equal length
    block.append_zeros(3);
    block.append<std::uint32_t>(1);
    block.append<std::uint64_t>(group.data_bytes_written);
    if (Status written = write_at(end, block.bytes().data(), block.size()); !written) return written;
    end += block.size();
    const std::uint64_t link_field = group.last_list == 0 ? group.described.dg_offset + format::link(format::dg::data)
                                                          : group.last_list + format::link(format::dl::next);
    if (Status linked = patch<std::uint64_t>(link_field, list_offset); !linked) return linked;
    group.last_list = list_offset;
    group.data_bytes_written += data_size;
    group.records_written += group.records_pending;
    group.records_pending = 0;
    start_pending(block);
    return done();
  }

  [[nodiscard]] Status usable() const {
    if (!failure.empty()) return Failure{failure};
    if (finalised) return Failure{path.string() + ": the MDF file is finalised; nothing more can be written"};
    return done();
  }
};

Writer::Writer(std::unique_ptr<State> state) : state_(std::move(state)) {}
Writer::Writer(Writer&&) noexcept = default;
Writer& Writer::operator=(Writer&&) noexcept = default;

Writer::~Writer() {
  if (state_ && !state_->finalised && state_->failure.empty()) (void)finalise();
}

Result<Writer> Writer::create(const std::filesystem::path& path, const FileSpec& spec, WriterOptions options) {
  if (const std::string problem = check_spec(spec); !problem.empty()) return Failure{path.string() + ": " + problem};
  auto state = std::make_unique<State>();
  state->path = path;
  state->options = options;
  state->file = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (state->file < 0) return Failure{path.string() + ": cannot create: " + std::strerror(errno)};
  const auto now =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch());
  FileDescription description = describe_file(spec, duet::version, now.count());
  for (std::size_t index = 0; index < spec.groups.size(); ++index) {
    GroupState group;
    group.name = spec.groups[index].name;
    group.described = description.groups[index];
    group.channel_names = channel_names(spec.groups[index]);
    start_pending(group.pending);
    state->groups.push_back(std::move(group));
  }
  if (Status written = state->write_at(0, description.image.bytes().data(), description.image.size()); !written)
    return Failure{written.error()};
  state->end = description.image.size();
  return Writer{std::move(state)};
}

Status Writer::append(std::size_t group_index, double time_s, std::span<const Value> values) {
  if (Status status = state_->usable(); !status) return status;
  if (group_index >= state_->groups.size())
    return Failure{state_->path.string() + ": there is no group " + std::to_string(group_index) + " (the file has " +
                   std::to_string(state_->groups.size()) + ")"};
  GroupState& group = state_->groups[group_index];
  const std::string where =
      state_->path.string() + ": group " + std::to_string(group_index) + " ('" + group.name + "')";
  const RecordLayout& layout = group.described.layout;
  if (values.size() != layout.types.size())
    return Failure{where + " has " + std::to_string(layout.types.size()) + " values per sample, not " +
                   std::to_string(values.size())};
  if (!std::isfinite(time_s) || time_s < group.last_time)
    return Failure{where + ": sample time " + std::to_string(time_s) + " s is not finite or goes back in time"};
  for (std::size_t channel = 0; channel < values.size(); ++channel) {
    const std::size_t expected = static_cast<std::size_t>(layout.types[channel]) + 1;
    if (values[channel].index() != 0 && values[channel].index() != expected)
      return Failure{where + ": channel '" + group.channel_names[channel] + "' is " + type_name(expected) +
                     ", the sample gave " + type_name(values[channel].index())};
  }
  ByteBuffer& pending = group.pending;
  const std::uint64_t record = pending.size();
  pending.append_zeros(layout.record_bytes());
  std::uint8_t* bytes = pending.bytes().data() + record;
  store(bytes, time_s);
  std::uint8_t* invalidation = bytes + layout.data_bytes;
  for (std::size_t channel = 0; channel < values.size(); ++channel) {
    std::uint8_t* at = bytes + layout.byte_offsets[channel];
    std::visit(
        [&](auto value) {
          using T = decltype(value);
          if constexpr (std::is_same_v<T, std::monostate>) {
            invalidation[channel / 8] = static_cast<std::uint8_t>(invalidation[channel / 8] | (1u << (channel % 8)));
          } else if constexpr (std::is_same_v<T, bool>) {
            *at = value ? 1 : 0;
          } else {
            store(at, value);
          }
        },
        values[channel]);
  }
  group.last_time = time_s;
  ++group.records_pending;
  if (pending.size() - format::header_size >= state_->options.fragment_bytes) return state_->write_fragment(group);
  return done();
}

Status Writer::flush() {
  if (Status status = state_->usable(); !status) return status;
  for (GroupState& group : state_->groups) {
    if (Status written = state_->write_fragment(group); !written) return written;
  }
  return done();
}

Status Writer::finalise() {
  if (Status flushed = flush(); !flushed) return flushed;
  for (const GroupState& group : state_->groups) {
    const std::uint64_t count = group.described.cg_offset + format::link(format::cg::links) + format::cg::cycle_count;
    if (Status patched = state_->patch<std::uint64_t>(count, group.records_written); !patched) return patched;
  }
  // The counts reach the disk before the identification says they are right.
  if (::fdatasync(state_->file) != 0) return state_->fail("sync");
  const std::uint8_t finalised_id[] = {'M', 'D', 'F', ' ', ' ', ' ', ' ', ' '};
  if (Status marked = state_->write_at(format::id::file_id, finalised_id, sizeof finalised_id); !marked) return marked;
  if (Status flags = state_->patch<std::uint16_t>(format::id::unfinalised_flags, 0); !flags) return flags;
  if (::fdatasync(state_->file) != 0) return state_->fail("sync");
  state_->finalised = true;
  ::close(state_->file);
  state_->file = -1;
  return done();
}

}  // namespace duet::mdf4
