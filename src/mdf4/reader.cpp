#include "duet/mdf4/reader.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <utility>

#include "blocks.hpp"
#include "data_stream.hpp"
#include "format.hpp"
#include "xml_text.hpp"

namespace duet::mdf4 {
namespace {

// Longer records than any recorder writes, and more than a 32-bit reader should allocate for one.
constexpr std::uint64_t longest_record = std::uint64_t{64} << 20;

// A data group: its channel groups (several only when records carry ids), and where its records are.
struct DataGroup {
  std::uint64_t offset = 0;
  std::uint8_t record_id_size = 0;
  std::vector<std::size_t> groups;  // indexes into FileInfo::groups
  std::vector<DataPiece> pieces;
  std::vector<Block> blocks;  // the DT blocks, before their lengths are checked (and recovered)
};

std::string trimmed(const std::uint8_t* bytes, std::size_t count) {
  std::string text{reinterpret_cast<const char*>(bytes), count};
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
  return text;
}

// The bytes a decoded channel's value takes from its byte offset on; 0 if duet does not decode it.
std::uint32_t value_bytes(const ChannelInfo& channel) {
  if (!channel.decoded || channel.role == ChannelInfo::Role::virtual_master) return 0;
  return (channel.bit_offset + channel.bit_count + 7) / 8;
}

bool decodable(std::uint8_t data_type, std::uint32_t bit_offset, std::uint32_t bit_count) {
  using namespace format::data_type;
  if (bit_count == 0 || bit_offset > 7 || bit_offset + bit_count > 64) return false;
  if (data_type == unsigned_le || data_type == signed_le) return true;
  if (data_type == unsigned_be || data_type == signed_be) return bit_offset == 0 && bit_count % 8 == 0;
  if (data_type == float_le || data_type == float_be) return bit_offset == 0 && (bit_count == 32 || bit_count == 64);
  return false;
}

}  // namespace

struct Reader::State {
  std::unique_ptr<ByteSource> source;
  FileInfo info;
  std::vector<DataGroup> data_groups;
  std::vector<std::size_t> data_group_of;  // per group

  [[nodiscard]] std::string name() const { return source->name(); }

  Result<Conversion> read_conversion(BlockReader& blocks, std::uint64_t offset, const std::string& via) {
    Conversion conversion;
    if (offset == 0) return conversion;
    auto read = blocks.read_shared(offset, {"CC"}, via);
    if (!read) return Failure{read.error()};
    const Block& block = read.value();
    const std::uint64_t data = 0;
    if (block.data.size() < format::cc::values)
      return Failure{blocks.here(offset) + ": ##CC block too short for its fields"};
    conversion.cc_type = block.field<std::uint8_t>(data + format::cc::type);
    const auto ref_count = block.field<std::uint16_t>(format::cc::ref_count);
    const auto value_count = block.field<std::uint16_t>(format::cc::value_count);
    if (block.links.size() < format::cc::links + std::size_t{ref_count})
      return Failure{blocks.here(offset) + ": ##CC block has " + std::to_string(block.links.size()) +
                     " links, fewer than its 4 and " + std::to_string(ref_count) + " references"};
    if (block.data.size() < format::cc::values + 8ull * value_count)
      return Failure{blocks.here(offset) + ": ##CC block too short for its " + std::to_string(value_count) + " values"};
    const auto value = [&](std::size_t index) { return block.field<double>(format::cc::values + 8 * index); };
    switch (conversion.cc_type) {
      case format::cc::identity: break;
      case format::cc::linear:
        if (value_count < 2) return Failure{blocks.here(offset) + ": linear ##CC block with fewer than 2 values"};
        conversion.kind = Conversion::Kind::linear;
        conversion.offset = value(0);
        conversion.factor = value(1);
        break;
      case format::cc::value_to_text: {
        if (ref_count != value_count + 1u)
          return Failure{blocks.here(offset) + ": value-to-text ##CC block with " + std::to_string(value_count) +
                         " keys needs " + std::to_string(value_count + 1) + " references, not " +
                         std::to_string(ref_count)};
        conversion.kind = Conversion::Kind::value_to_text;
        for (std::size_t index = 0; index <= value_count; ++index) {
          const std::uint64_t reference = block.link(format::cc::links + index);
          // A reference may also be a conversion (a scaling): not applied, the key's text then is empty.
          std::string text;
          if (reference != 0) {
            auto referenced =
                blocks.read_shared(reference, {"TX", "MD", "CC"}, "a reference of the ##CC at " + hex(offset));
            if (!referenced) return Failure{referenced.error()};
            if (referenced.value().id != "CC") {
              auto read_text = blocks.text(reference, "a text of the ##CC at " + hex(offset));
              if (!read_text) return Failure{read_text.error()};
              text = read_text.value();
            }
          }
          if (index < value_count) {
            conversion.texts.emplace_back(value(index), text);
          } else {
            conversion.default_text = text;
          }
        }
        break;
      }
      default: conversion.kind = Conversion::Kind::unsupported;
    }
    return conversion;
  }

  Result<ChannelInfo> read_channel(BlockReader& blocks, const Block& block, const GroupInfo& group) {
    const std::string where = blocks.here(block.offset) + ": ##CN block";
    if (block.data.size() < format::cn::invalidation_bit + 4)
      return Failure{where + " too short for its fields (" + std::to_string(block.length) + " bytes)"};
    ChannelInfo channel;
    channel.block_offset = block.offset;
    const auto via = [&](const char* what) { return std::string{what} + " of the ##CN at " + hex(block.offset); };
    auto name = blocks.text(block.link(format::cn::name), via("the name"));
    if (!name) return Failure{name.error()};
    channel.name = name.value();
    auto unit = blocks.text(block.link(format::cn::unit), via("the unit"));
    if (!unit) return Failure{unit.error()};
    channel.unit = unit.value();
    auto comment = blocks.text(block.link(format::cn::comment), via("the comment"));
    if (!comment) return Failure{comment.error()};
    channel.comment = comment.value();
    auto conversion = read_conversion(blocks, block.link(format::cn::conversion), via("the conversion"));
    if (!conversion) return Failure{conversion.error()};
    channel.conversion = conversion.value();

    const auto type = block.field<std::uint8_t>(format::cn::type);
    channel.data_type = block.field<std::uint8_t>(format::cn::data_type);
    channel.bit_offset = block.field<std::uint8_t>(format::cn::bit_offset);
    channel.byte_offset = block.field<std::uint32_t>(format::cn::byte_offset);
    channel.bit_count = block.field<std::uint32_t>(format::cn::bit_count);
    const auto flags = block.field<std::uint32_t>(format::cn::flags);
    if (type == format::cn::master) channel.role = ChannelInfo::Role::master;
    if (type == format::cn::virtual_master || type == format::cn::virtual_data) {
      // Its stored value is the record's index, unsigned, which its conversion may scale.
      if (type == format::cn::virtual_master) channel.role = ChannelInfo::Role::virtual_master;
      channel.data_type = format::data_type::unsigned_le;
      channel.bit_count = 0;
    } else {
      const bool fixed_length =
          type == format::cn::fixed_length || type == format::cn::master || type == format::cn::synchronisation;
      channel.decoded = fixed_length && decodable(channel.data_type, channel.bit_offset, channel.bit_count);
    }
    if ((flags & 1u) != 0) channel.invalidation_bit = std::numeric_limits<std::uint32_t>::max();  // all invalid
    if ((flags & format::cn::invalidation_bit_valid) != 0) {
      channel.invalidation_bit = block.field<std::uint32_t>(format::cn::invalidation_bit);
      if (*channel.invalidation_bit >= 8ull * group.invalidation_bytes)
        return Failure{where + " '" + channel.name + "': invalidation bit " +
                       std::to_string(*channel.invalidation_bit) + " lies outside the record's " +
                       std::to_string(group.invalidation_bytes) + " invalidation bytes"};
    }
    if (const std::uint32_t bytes = value_bytes(channel);
        bytes > 0 && std::uint64_t{channel.byte_offset} + bytes > group.data_bytes)
      return Failure{where + " '" + channel.name + "': its value (bytes " + std::to_string(channel.byte_offset) +
                     " to " + std::to_string(std::uint64_t{channel.byte_offset} + bytes - 1) +
                     ") lies outside the record's " + std::to_string(group.data_bytes) + " data bytes"};
    return channel;
  }

  Result<GroupInfo> read_group(BlockReader& blocks, const Block& block) {
    const std::string where = blocks.here(block.offset) + ": ##CG block";
    const std::uint64_t data = 0;  // after all links: 4.2's seventh (the remote master) moves it, as any link does
    if (block.links.size() < format::cg::links || block.data.size() < data + format::cg::data_size)
      return Failure{where + " too short for its fields (" + std::to_string(block.length) + " bytes)"};
    GroupInfo group;
    group.block_offset = block.offset;
    group.record_id = block.field<std::uint64_t>(data + format::cg::record_id);
    group.samples = block.field<std::uint64_t>(data + format::cg::cycle_count);
    const auto flags = block.field<std::uint16_t>(data + format::cg::flags);
    group.data_bytes = block.field<std::uint32_t>(data + format::cg::data_bytes);
    group.invalidation_bytes = block.field<std::uint32_t>(data + format::cg::invalidation_bytes);
    if ((flags & 1u) != 0) return Failure{where + ": variable-length (VLSD) channel groups are not supported"};
    const std::uint64_t record_bytes = std::uint64_t{group.data_bytes} + group.invalidation_bytes;
    if (record_bytes == 0) return Failure{where + ": its records have no bytes"};
    if (record_bytes > longest_record)
      return Failure{where + ": its records of " + std::to_string(record_bytes) + " bytes are implausibly long"};
    auto name = blocks.text(block.link(format::cg::acquisition_name),
                            "the acquisition name of the ##CG at " + hex(block.offset));
    if (!name) return Failure{name.error()};
    group.name = name.value();
    auto comment = blocks.text(block.link(format::cg::comment), "the comment of the ##CG at " + hex(block.offset));
    if (!comment) return Failure{comment.error()};
    group.comment = comment.value();
    std::string via = "the first ##CN of the ##CG at " + hex(block.offset);
    for (std::uint64_t next = block.link(format::cg::cn_first); next != 0;) {
      auto channel_block = blocks.read(next, {"CN"}, via);
      if (!channel_block) return Failure{channel_block.error()};
      auto channel = read_channel(blocks, channel_block.value(), group);
      if (!channel) return Failure{channel.error()};
      if (channel.value().role != ChannelInfo::Role::value) {
        if (group.master)
          return Failure{blocks.here(next) + ": ##CN block '" + channel.value().name +
                         "' is a second master channel of its group"};
        group.master = group.channels.size();
      }
      group.channels.push_back(channel.value());
      via = "the next ##CN of the ##CN at " + hex(next);
      next = channel_block.value().link(format::cn::next);
    }
    return group;
  }

  // The DT blocks of a data group: a DT, or a DL chain (possibly under an HL).
  Status read_data_blocks(BlockReader& blocks, DataGroup& group, std::uint64_t link) const {
    if (link == 0) return done();
    auto first = blocks.read_data_header(link, "the data of the ##DG at " + hex(group.offset));
    if (first && first.value().id == "DT") {
      group.blocks.push_back(first.value());
      return done();
    }
    auto list = blocks.read(link, {"DL", "HL", "DZ"}, "the data of the ##DG at " + hex(group.offset));
    if (!list) return Failure{list.error()};
    std::string via = "the data list of the ##DG at " + hex(group.offset);
    std::uint64_t next = link;
    if (list.value().id == "DZ") return Failure{blocks.here(link) + ": compressed data (##DZ) is not supported"};
    if (list.value().id == "HL") {
      via = "the ##HL at " + hex(link);
      next = list.value().link(format::hl::dl_first);
      if (next == 0) return done();
      list = blocks.read(next, {"DL"}, via);
      if (!list) return Failure{list.error()};
    }
    const bool nil_ends_list = (info.unfinalised_flags & format::id::last_dl_flag) != 0;
    while (true) {
      const Block& dl = list.value();
      if (dl.links.empty() || dl.data.size() < format::dl::count + 4)
        return Failure{blocks.here(next) + ": ##DL block too short for its fields"};
      const auto count = dl.field<std::uint32_t>(format::dl::count);
      if (count != dl.links.size() - 1)
        return Failure{blocks.here(next) + ": ##DL block lists " + std::to_string(count) + " data blocks in " +
                       std::to_string(dl.links.size() - 1) + " links"};
      for (std::size_t index = 1; index < dl.links.size(); ++index) {
        if (dl.links[index] == 0) {
          if (nil_ends_list) break;  // an unfinalised list: the writer had not filled it yet
          return Failure{blocks.here(next) + ": ##DL block's data link " + std::to_string(index - 1) + " is NIL"};
        }
        auto data_block = blocks.read_data_header(
            dl.links[index], "data link " + std::to_string(index - 1) + " of the ##DL at " + hex(next));
        if (!data_block) {
          auto compressed = blocks.read(dl.links[index], {"DZ"}, "a data link of the ##DL at " + hex(next));
          if (compressed) return Failure{blocks.here(dl.links[index]) + ": compressed data (##DZ) is not supported"};
          return Failure{data_block.error()};
        }
        group.blocks.push_back(data_block.value());
      }
      const std::uint64_t following = dl.link(format::dl::next);
      if (following == 0) return done();
      list = blocks.read(following, {"DL"}, "the next ##DL of the ##DL at " + hex(next));
      if (!list) return Failure{list.error()};
      next = following;
    }
  }

  Status read_structure() {
    BlockReader blocks{*source};
    std::uint8_t id[format::id::size];
    if (source->size() < format::id::size || !source->read(0, id, sizeof id))
      return Failure{name() + ": not an MDF file (" + std::to_string(source->size()) +
                     " bytes, fewer than the 64 of an MDF identification block)"};
    const std::string file_id = trimmed(id, 8);
    if (file_id != "MDF" && file_id != "UnFinMF")
      return Failure{name() + ": not an MDF file (it starts with \"" + trimmed(id, 8) + R"(", not "MDF"))"};
    info.version = trimmed(id + format::id::version_text, 8);
    info.program = trimmed(id + format::id::program, 8);
    info.version_number = load<std::uint16_t>(id + format::id::version_number);
    if (info.version_number < 400 || info.version_number >= 500)
      return Failure{name() + ": MDF version " + info.version + " (" + std::to_string(info.version_number) +
                     "); duet reads MDF 4 only"};
    info.unfinalised_flags = load<std::uint16_t>(id + format::id::unfinalised_flags);
    info.finalised = file_id == "MDF" && info.unfinalised_flags == 0;

    auto header = blocks.read(format::hd_offset, {"HD"}, "the identification block");
    if (!header) return Failure{header.error()};
    info.start_time_ns = header.value().field<std::uint64_t>(format::hd::start_time_ns - 72);
    std::string via = "the file history of the ##HD";
    for (std::uint64_t next = header.value().link(format::hd::fh_first); next != 0;) {
      auto history = blocks.read(next, {"FH"}, via);
      if (!history) return Failure{history.error()};
      auto comment = blocks.read_shared(history.value().link(format::fh::comment), {"TX", "MD"},
                                        "the comment of the ##FH at " + hex(next));
      if (history.value().link(format::fh::comment) != 0) {
        if (!comment) return Failure{comment.error()};
        const std::vector<std::uint8_t>& bytes = comment.value().data;
        const std::string xml{bytes.begin(), std::find(bytes.begin(), bytes.end(), std::uint8_t{0})};
        const std::string tool = element_text(xml, "tool_id");
        const std::string version = element_text(xml, "tool_version");
        std::string named = tool.empty() ? text_of_xml(xml) : tool;
        if (!tool.empty() && !version.empty()) named += " " + version;
        info.history.push_back(named);
      }
      via = "the next ##FH of the ##FH at " + hex(next);
      next = history.value().link(format::fh::next);
    }

    via = "the first ##DG of the ##HD";
    for (std::uint64_t next = header.value().link(format::hd::dg_first); next != 0;) {
      auto block = blocks.read(next, {"DG"}, via);
      if (!block) return Failure{block.error()};
      if (block.value().links.size() < format::dg::links || block.value().data.empty())
        return Failure{blocks.here(next) + ": ##DG block too short for its fields"};
      DataGroup data_group;
      data_group.offset = next;
      data_group.record_id_size = block.value().field<std::uint8_t>(format::dg::record_id_size - 56);
      if (data_group.record_id_size != 0 && data_group.record_id_size != 1 && data_group.record_id_size != 2 &&
          data_group.record_id_size != 4 && data_group.record_id_size != 8)
        return Failure{blocks.here(next) + ": ##DG block's record id size " +
                       std::to_string(data_group.record_id_size) + " is not 0, 1, 2, 4 or 8"};
      std::string cg_via = "the first ##CG of the ##DG at " + hex(next);
      for (std::uint64_t cg = block.value().link(format::dg::cg_first); cg != 0;) {
        auto cg_block = blocks.read(cg, {"CG"}, cg_via);
        if (!cg_block) return Failure{cg_block.error()};
        auto group = read_group(blocks, cg_block.value());
        if (!group) return Failure{group.error()};
        if (data_group.record_id_size == 0 && !data_group.groups.empty())
          return Failure{blocks.here(cg) + ": a second ##CG in the ##DG at " + hex(next) +
                         ", whose records have no record ids"};
        data_group.groups.push_back(info.groups.size());
        data_group_of.push_back(data_groups.size());
        info.groups.push_back(std::move(group.value()));
        cg_via = "the next ##CG of the ##CG at " + hex(cg);
        cg = cg_block.value().link(format::cg::next);
      }
      if (Status data = read_data_blocks(blocks, data_group, block.value().link(format::dg::data)); !data) return data;
      data_groups.push_back(std::move(data_group));
      via = "the next ##DG of the ##DG at " + hex(next);
      next = block.value().link(format::dg::next);
    }
    return place_data(blocks);
  }

  // The data blocks' lengths checked (the last one recovered if the writer had not updated it), then the samples.
  Status place_data(BlockReader& blocks) {
    if ((info.unfinalised_flags & format::id::last_dt_length_flag) != 0) {
      Block* last = nullptr;
      for (DataGroup& group : data_groups) {
        for (Block& block : group.blocks) {
          if (last == nullptr || block.offset > last->offset) last = &block;
        }
      }
      if (last != nullptr) last->length = blocks.next_block_after(last->offset) - last->offset;
    }
    for (DataGroup& group : data_groups) {
      for (const Block& block : group.blocks) {
        if (Status claimed = blocks.claim_data(block); !claimed) return claimed;
        group.pieces.push_back({block.offset + format::header_size, block.length - format::header_size});
      }
      group.blocks = {};  // only the pieces are kept: 16 bytes per data block
      if (Status counted = count_samples(blocks, group); !counted) return counted;
    }
    return done();
  }

  Status count_samples(BlockReader& blocks, const DataGroup& data_group) {
    std::uint64_t data_bytes = 0;
    for (const DataPiece& piece : data_group.pieces) data_bytes += piece.size;
    const bool recount = (info.unfinalised_flags & format::id::cycle_counts_flag) != 0;
    if (data_group.record_id_size == 0) {
      if (data_group.groups.empty()) return done();
      GroupInfo& group = info.groups[data_group.groups.front()];
      const std::uint64_t record_bytes = std::uint64_t{group.data_bytes} + group.invalidation_bytes;
      const std::uint64_t held = data_bytes / record_bytes;
      if (recount) {
        group.samples = held;  // a record torn by a crash is dropped
      } else if (group.samples > held) {
        return Failure{blocks.here(group.block_offset) + ": ##CG block counts " + std::to_string(group.samples) +
                       " samples of " + std::to_string(record_bytes) + " bytes; its data holds " +
                       std::to_string(data_bytes) + " bytes"};
      }
      return done();
    }
    // Records with ids: count each group's by walking them.
    std::map<std::uint64_t, std::size_t> by_id;
    for (const std::size_t index : data_group.groups) {
      if (!by_id.emplace(info.groups[index].record_id, index).second)
        return Failure{blocks.here(info.groups[index].block_offset) + ": ##CG block's record id " +
                       std::to_string(info.groups[index].record_id) + " is also another group's"};
    }
    std::map<std::size_t, std::uint64_t> counted;
    DataStream stream{*source, data_group.pieces};
    for (std::uint64_t at = 0;;) {
      const std::span<const std::uint8_t> id_bytes = stream.next(data_group.record_id_size);
      if (id_bytes.empty()) break;
      std::uint64_t id = 0;
      std::memcpy(&id, id_bytes.data(), id_bytes.size());
      const auto group = by_id.find(id);
      if (group == by_id.end()) {
        if (recount) break;  // the writer's last record, torn
        return Failure{blocks.here(data_group.offset) + ": ##DG data byte " + std::to_string(at) + " has record id " +
                       std::to_string(id) + ", which no ##CG of it has"};
      }
      const GroupInfo& info_group = info.groups[group->second];
      const std::size_t record_bytes = info_group.record_bytes();
      if (stream.next(record_bytes).empty()) break;  // torn at the end
      ++counted[group->second];
      at += data_group.record_id_size + record_bytes;
    }
    if (stream.failed()) return Failure{name() + ": cannot read the data of the ##DG at " + hex(data_group.offset)};
    for (const std::size_t index : data_group.groups) {
      GroupInfo& group = info.groups[index];
      if (recount) {
        group.samples = counted[index];
      } else if (group.samples > counted[index]) {
        return Failure{blocks.here(group.block_offset) + ": ##CG block counts " + std::to_string(group.samples) +
                       " samples; its data group holds " + std::to_string(counted[index])};
      }
    }
    return done();
  }
};

Reader::Reader(std::unique_ptr<State> state) : state_(std::move(state)) {}
Reader::Reader(Reader&&) noexcept = default;
Reader& Reader::operator=(Reader&&) noexcept = default;
Reader::~Reader() = default;

Result<Reader> Reader::open(const std::filesystem::path& path) {
  auto source = open_file_source(path);
  if (!source) return Failure{source.error()};
  auto state = std::make_unique<State>();
  state->source = std::move(source.value());
  if (Status read = state->read_structure(); !read) return Failure{read.error()};
  return Reader{std::move(state)};
}

Result<Reader> Reader::from_bytes(std::vector<std::uint8_t> bytes, std::string name) {
  auto state = std::make_unique<State>();
  state->source = memory_source(std::move(bytes), std::move(name));
  if (Status read = state->read_structure(); !read) return Failure{read.error()};
  return Reader{std::move(state)};
}

const FileInfo& Reader::info() const { return state_->info; }

struct RecordCursor::State {
  const ByteSource& source;
  const FileInfo& info;
  const GroupInfo& group;
  const DataGroup& data_group;
  DataStream stream;
  std::uint64_t index = 0;
  std::string error;
};

RecordCursor::RecordCursor(std::unique_ptr<State> state) : state_(std::move(state)) {}
RecordCursor::RecordCursor(RecordCursor&&) noexcept = default;
RecordCursor& RecordCursor::operator=(RecordCursor&&) noexcept = default;
RecordCursor::~RecordCursor() = default;
const std::string& RecordCursor::error() const { return state_->error; }

std::optional<Record> RecordCursor::next() {
  State& state = *state_;
  const GroupInfo& group = state.group;
  const std::size_t record_bytes = group.record_bytes();
  while (state.index < group.samples) {
    if (state.data_group.record_id_size != 0) {
      const std::span<const std::uint8_t> id_bytes = state.stream.next(state.data_group.record_id_size);
      if (id_bytes.empty()) break;
      std::uint64_t id = 0;
      std::memcpy(&id, id_bytes.data(), id_bytes.size());
      if (id != group.record_id) {
        // Counted on opening: every id belongs to a group of this data group, and each is read past.
        for (const std::size_t other : state.data_group.groups) {
          const GroupInfo& other_group = state.info.groups[other];
          if (other_group.record_id == id) (void)state.stream.next(other_group.record_bytes());
        }
        continue;
      }
    }
    const std::span<const std::uint8_t> bytes = state.stream.next(record_bytes);
    if (bytes.empty()) break;
    return Record{group, bytes, state.index++};
  }
  if (state.stream.failed() && state.error.empty())
    state.error = state.source.name() + ": cannot read the data of the ##DG at " + hex(state.data_group.offset);
  return std::nullopt;
}

RecordCursor Reader::records(std::size_t group) const {
  const DataGroup& data_group = state_->data_groups[state_->data_group_of[group]];
  return RecordCursor{std::make_unique<RecordCursor::State>(
      RecordCursor::State{.source = *state_->source,
                          .info = state_->info,
                          .group = state_->info.groups[group],
                          .data_group = data_group,
                          .stream = DataStream{*state_->source, data_group.pieces},
                          .index = 0,
                          .error = {}})};
}

Status Reader::for_each_record(std::size_t group, const std::function<void(const Record&)>& visit) const {
  if (group >= state_->info.groups.size())
    return Failure{state_->name() + ": there is no group " + std::to_string(group)};
  RecordCursor cursor = records(group);
  while (const std::optional<Record> record = cursor.next()) visit(*record);
  if (!cursor.error().empty()) return Failure{cursor.error()};
  return done();
}

Result<std::optional<std::pair<double, double>>> Reader::time_span(std::size_t group) const {
  using Span = std::optional<std::pair<double, double>>;
  if (group >= info().groups.size() || !info().groups[group].master || info().groups[group].samples == 0) return Span{};
  const GroupInfo& info_group = info().groups[group];
  const DataGroup& data_group = state_->data_groups[state_->data_group_of[group]];
  if (data_group.record_id_size != 0) {  // records with ids: only a walk finds the last
    Span span;
    Status read = for_each_record(group, [&](const Record& record) {
      if (!span) span = std::pair{record.time(), record.time()};
      span->second = record.time();
    });
    if (!read) return Failure{read.error()};
    return span;
  }
  // Sorted: the first record, and the last one found from the blocks' sizes.
  const std::size_t record_bytes = info_group.record_bytes();
  std::vector<std::uint8_t> bytes(record_bytes);
  const auto time_of = [&](std::uint64_t index) -> std::optional<double> {
    std::uint64_t skip = index * record_bytes;
    std::size_t filled = 0;
    for (const DataPiece& piece : data_group.pieces) {
      if (skip >= piece.size) {
        skip -= piece.size;
        continue;
      }
      const auto take = static_cast<std::size_t>(std::min<std::uint64_t>(piece.size - skip, record_bytes - filled));
      if (!state_->source->read(piece.offset + skip, bytes.data() + filled, take)) return std::nullopt;
      filled += take;
      skip = 0;
      if (filled == record_bytes) return Record{info_group, bytes, index}.time();
    }
    return std::nullopt;
  };
  const std::optional<double> first = time_of(0);
  const std::optional<double> last = time_of(info_group.samples - 1);
  if (!first || !last)
    return Failure{state_->name() + ": cannot read the data of the ##DG at " + hex(data_group.offset)};
  return Span{std::pair{*first, *last}};
}

}  // namespace duet::mdf4
