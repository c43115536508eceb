#include "file_description.hpp"

#include <cstddef>
#include <map>
#include <string>

#include "format.hpp"

namespace duet::mdf4 {
namespace {

constexpr std::string_view version_text = "4.20    ";
constexpr std::uint16_t version_number = 420;

// Unsigned, signed or IEEE float, in MDF's little-endian data type codes.
std::uint8_t data_type_of(ValueType type) {
  switch (type) {
    case ValueType::boolean:
    case ValueType::u8:
    case ValueType::u16:
    case ValueType::u32:
    case ValueType::u64: return format::data_type::unsigned_le;
    case ValueType::i8:
    case ValueType::i16:
    case ValueType::i32:
    case ValueType::i64: return format::data_type::signed_le;
    case ValueType::f32:
    case ValueType::f64: return format::data_type::float_le;
  }
  return format::data_type::unsigned_le;
}

std::string escape_xml(std::string_view text) {
  std::string escaped;
  for (const char character : text) {
    switch (character) {
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '&': escaped += "&amp;"; break;
      default: escaped += character;
    }
  }
  return escaped;
}

class ImageBuilder {
 public:
  explicit ImageBuilder(ByteBuffer& image) : image_(image) {}

  // A block of `links` NIL links and `data_size` zero bytes of data, 8-byte aligned; returns its offset.
  std::uint64_t block(std::string_view id, unsigned links, std::size_t data_size) {
    image_.align(format::alignment);
    const std::uint64_t at = image_.size();
    image_.append_text(id);
    image_.append<std::uint32_t>(0);
    image_.append<std::uint64_t>(format::header_size + 8 * std::uint64_t{links} + data_size);
    image_.append<std::uint64_t>(links);
    image_.append_zeros(8 * std::size_t{links} + data_size);
    return at;
  }
  void link(std::uint64_t block, unsigned index, std::uint64_t target) {
    image_.put<std::uint64_t>(block + format::link(index), target);
  }
  template <typename T>
  void data(std::uint64_t block, unsigned links, std::uint64_t field, T value) {
    image_.put<T>(block + format::header_size + 8 * std::uint64_t{links} + field, value);
  }
  // A text block (`##TX` or `##MD`), zero-terminated and padded with zeros to 8 bytes, which its length includes;
  // equal plain texts share one block. An empty plain text is no block (NIL).
  std::uint64_t text(std::string_view text, std::string_view id = "##TX") {
    if (text.empty() && id == "##TX") return 0;
    const std::string key = std::string{id} + std::string{text};
    if (const auto found = texts_.find(key); found != texts_.end()) return found->second;
    const std::size_t padded = (text.size() + 1 + 7) / 8 * 8;
    const std::uint64_t at = block(id, 0, padded);
    std::copy(text.begin(), text.end(), image_.bytes().begin() + static_cast<std::ptrdiff_t>(at + format::header_size));
    texts_.emplace(key, at);
    return at;
  }

 private:
  ByteBuffer& image_;
  std::map<std::string, std::uint64_t> texts_;
};

void write_identification(ByteBuffer& image) {
  image.append_text("UnFinMF ");  // finalise() writes "MDF     " once the counts are right
  image.append_text(version_text);
  image.append_text("duet    ");
  image.append_zeros(4);
  image.append<std::uint16_t>(version_number);
  image.append_zeros(30);
  image.append<std::uint16_t>(format::id::cycle_counts_flag);
  image.append<std::uint16_t>(0);
}

std::uint64_t write_history(ImageBuilder& builder, std::string_view program_version, std::int64_t now_ns) {
  const std::uint64_t history = builder.block("##FH", format::fh::links, format::fh::size - 40);
  const std::string comment =
      "<FHcomment xmlns=\"http://www.asam.net/mdf/v4\"><TX>written by duet</TX>"
      "<tool_id>duet</tool_id><tool_vendor>duet</tool_vendor><tool_version>" +
      escape_xml(program_version) + "</tool_version></FHcomment>";
  builder.link(history, format::fh::comment, builder.text(comment, "##MD"));
  builder.data<std::uint64_t>(history, format::fh::links, 0, static_cast<std::uint64_t>(now_ns));
  return history;
}

std::uint64_t write_channel(ImageBuilder& builder, std::string_view name, std::uint8_t type, std::uint8_t sync,
                            std::uint8_t data_type, std::uint32_t byte_offset, std::uint32_t bits) {
  const std::uint64_t channel = builder.block("##CN", format::cn::links, format::cn::data_size);
  constexpr unsigned links = format::cn::links;
  builder.data<std::uint8_t>(channel, links, format::cn::type, type);
  builder.data<std::uint8_t>(channel, links, format::cn::sync_type, sync);
  builder.data<std::uint8_t>(channel, links, format::cn::data_type, data_type);
  builder.data<std::uint32_t>(channel, links, format::cn::byte_offset, byte_offset);
  builder.data<std::uint32_t>(channel, links, format::cn::bit_count, bits);
  builder.link(channel, format::cn::name, builder.text(name));
  return channel;
}

std::uint64_t write_linear(ImageBuilder& builder, const Linear& linear) {
  const std::uint64_t conversion = builder.block("##CC", format::cc::links, 24 + 16);
  builder.data<std::uint8_t>(conversion, format::cc::links, format::cc::type, format::cc::linear);
  builder.data<std::uint16_t>(conversion, format::cc::links, format::cc::value_count, 2);
  builder.data<double>(conversion, format::cc::links, format::cc::values, linear.offset);
  builder.data<double>(conversion, format::cc::links, format::cc::values + 8, linear.factor);
  return conversion;
}

DescribedGroup write_group(ImageBuilder& builder, const GroupSpec& spec) {
  DescribedGroup group;
  RecordLayout& layout = group.layout;
  layout.data_bytes = 8;  // the time
  for (const ChannelSpec& channel : spec.channels) {
    for (std::size_t element = 0; element < channel.elements; ++element) {
      layout.types.push_back(channel.type);
      layout.byte_offsets.push_back(layout.data_bytes);
      layout.data_bytes += size_of(channel.type);
    }
  }
  layout.invalidation_bytes = static_cast<std::uint32_t>((layout.types.size() + 7) / 8);

  group.dg_offset = builder.block("##DG", format::dg::links, format::dg::size - 56);
  group.cg_offset = builder.block("##CG", format::cg::links, format::cg::data_size);
  builder.link(group.dg_offset, format::dg::cg_first, group.cg_offset);
  builder.data<std::uint32_t>(group.cg_offset, format::cg::links, format::cg::data_bytes, layout.data_bytes);
  builder.data<std::uint32_t>(group.cg_offset, format::cg::links, format::cg::invalidation_bytes,
                              layout.invalidation_bytes);

  // The time channel, then the values; channels' texts follow them so that the file never ends with a channel.
  const std::uint64_t time =
      write_channel(builder, "time", format::cn::master, format::cn::sync_time, format::data_type::float_le, 0, 64);
  builder.link(time, format::cn::unit, builder.text("s"));
  builder.link(group.cg_offset, format::cg::cn_first, time);
  std::uint64_t previous = time;
  std::size_t index = 0;
  for (const ChannelSpec& spec_channel : spec.channels) {
    const std::uint64_t conversion = spec_channel.conversion ? write_linear(builder, *spec_channel.conversion) : 0;
    for (std::size_t element = 0; element < spec_channel.elements; ++element, ++index) {
      const std::string name =
          spec_channel.elements == 1 ? spec_channel.name : spec_channel.name + "[" + std::to_string(element) + "]";
      const std::uint64_t channel =
          write_channel(builder, name, format::cn::fixed_length, 0, data_type_of(layout.types[index]),
                        layout.byte_offsets[index], 8 * size_of(layout.types[index]));
      builder.data<std::uint32_t>(channel, format::cn::links, format::cn::flags, format::cn::invalidation_bit_valid);
      builder.data<std::uint32_t>(channel, format::cn::links, format::cn::invalidation_bit,
                                  static_cast<std::uint32_t>(index));
      builder.link(channel, format::cn::conversion, conversion);
      builder.link(channel, format::cn::unit, builder.text(spec_channel.unit));
      builder.link(channel, format::cn::comment, builder.text(spec_channel.comment));
      builder.link(previous, format::cn::next, channel);
      previous = channel;
    }
  }
  builder.link(group.cg_offset, format::cg::acquisition_name, builder.text(spec.name));
  builder.link(group.cg_offset, format::cg::comment, builder.text(spec.comment));
  return group;
}

}  // namespace

std::uint32_t size_of(ValueType type) {
  switch (type) {
    case ValueType::boolean:
    case ValueType::u8:
    case ValueType::i8: return 1;
    case ValueType::u16:
    case ValueType::i16: return 2;
    case ValueType::u32:
    case ValueType::i32:
    case ValueType::f32: return 4;
    case ValueType::u64:
    case ValueType::i64:
    case ValueType::f64: return 8;
  }
  return 8;
}

FileDescription describe_file(const FileSpec& spec, std::string_view program_version, std::int64_t now_ns) {
  FileDescription description;
  write_identification(description.image);
  ImageBuilder builder{description.image};
  const std::uint64_t header = builder.block("##HD", format::hd::links, format::hd::size - 72);
  builder.data<std::uint64_t>(header, format::hd::links, 0, static_cast<std::uint64_t>(spec.start_time_ns));
  builder.link(header, format::hd::comment, builder.text(spec.comment));
  std::uint64_t previous = 0;
  for (const GroupSpec& group_spec : spec.groups) {
    const DescribedGroup group = write_group(builder, group_spec);
    if (previous == 0) {
      builder.link(header, format::hd::dg_first, group.dg_offset);
    } else {
      builder.link(previous, format::dg::next, group.dg_offset);
    }
    previous = group.dg_offset;
    description.groups.push_back(group);
  }
  // The history last: its XML is a block of its own, so the description never ends with a channel, which a reader
  // recovering an unfinalised file may read past (a text or a group's channel may have been shared, and written
  // before).
  builder.link(header, format::hd::fh_first, write_history(builder, program_version, now_ns));
  description.image.align(format::alignment);
  return description;
}

}  // namespace duet::mdf4
