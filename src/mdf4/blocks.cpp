#include "blocks.hpp"

#include <algorithm>
#include <cstdio>

#include "format.hpp"
#include "xml_text.hpp"

namespace duet::mdf4 {
namespace {

// Metadata blocks are small; a longer one is damage, not a file duet could read in memory anyway.
constexpr std::uint64_t longest_metadata_block = 64ull << 20;

std::string printable(const std::uint8_t* bytes, std::size_t count) {
  std::string text;
  for (std::size_t index = 0; index < count; ++index) {
    const char character = static_cast<char>(bytes[index]);
    text += character >= 0x20 && character < 0x7f ? std::string{character} : "\\x" + hex(bytes[index]).substr(2);
  }
  return text;
}

std::string expected_ids(std::initializer_list<std::string_view> ids) {
  std::string text;
  for (const std::string_view id : ids) text += (text.empty() ? "##" : " or ##") + std::string{id};
  return text;
}

}  // namespace

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%llX", static_cast<unsigned long long>(value));
  return text;
}

std::string BlockReader::here(std::uint64_t offset) const { return source_.name() + ": at " + hex(offset); }

Status BlockReader::claim(std::uint64_t offset, std::uint64_t length, std::string_view what) {
  const std::uint64_t end = offset + length;
  auto after = claimed_.lower_bound(offset);
  if (after != claimed_.end() && after->first == offset)
    return Failure{here(offset) + ": " + std::string{what} +
                   " is reached a second time (a loop in the links, or a block linked twice)"};
  if (after != claimed_.end() && after->first < end)
    return Failure{here(offset) + ": " + std::string{what} + " (" + std::to_string(length) +
                   " bytes) overlaps the block at " + hex(after->first)};
  if (after != claimed_.begin() && std::prev(after)->second > offset)
    return Failure{here(offset) + ": " + std::string{what} + " lies inside the block at " +
                   hex(std::prev(after)->first)};
  claimed_.emplace(offset, end);
  return done();
}

Result<Block> BlockReader::header(std::uint64_t offset, std::initializer_list<std::string_view> ids,
                                  std::string_view via) {
  const std::uint64_t size = source_.size();
  if (offset < format::id::size || offset > size || size - offset < format::header_size)
    return Failure{source_.name() + ": " + std::string{via} + " links to " + hex(offset) +
                   (offset < format::id::size ? ", inside the identification block"
                                              : ", past the end of the file (" + std::to_string(size) + " bytes)")};
  std::uint8_t bytes[format::header_size];
  if (!source_.read(offset, bytes, sizeof bytes)) return Failure{here(offset) + ": cannot read"};
  Block block;
  block.offset = offset;
  const bool known_id =
      bytes[0] == '#' && bytes[1] == '#' && std::any_of(ids.begin(), ids.end(), [&](std::string_view id) {
        return id[0] == static_cast<char>(bytes[2]) && id[1] == static_cast<char>(bytes[3]);
      });
  if (!known_id)
    return Failure{here(offset) + ": expected " + expected_ids(ids) + " (" + std::string{via} + "), found \"" +
                   printable(bytes, 4) + "\""};
  block.id = std::string{static_cast<char>(bytes[2]), static_cast<char>(bytes[3])};
  block.length = load<std::uint64_t>(bytes + format::length_field);
  const auto link_count = load<std::uint64_t>(bytes + format::link_count_field);
  const std::string what = "##" + block.id + " block";
  if (block.length < format::header_size || link_count > (block.length - format::header_size) / 8)
    return Failure{here(offset) + ": " + what + " of length " + std::to_string(block.length) + " cannot hold its " +
                   std::to_string(link_count) + " links"};
  if (block.length > size - offset)
    return Failure{here(offset) + ": " + what + " of length " + std::to_string(block.length) +
                   " runs past the end of the file (" + std::to_string(size) + " bytes)"};
  if (link_count > longest_metadata_block / 8)
    return Failure{here(offset) + ": " + what + " has implausibly many links (" + std::to_string(link_count) + ")"};
  block.links.resize(static_cast<std::size_t>(link_count));
  return block;
}

Result<Block> BlockReader::read(std::uint64_t offset, std::initializer_list<std::string_view> ids,
                                std::string_view via) {
  auto read = header(offset, ids, via);
  if (!read) return read;
  Block& block = read.value();
  const std::string what = "##" + block.id + " block";
  if (block.length > longest_metadata_block)
    return Failure{here(offset) + ": " + what + " of length " + std::to_string(block.length) + " is implausibly long"};
  if (Status claimed = claim(offset, block.length, what); !claimed) return Failure{claimed.error()};
  std::vector<std::uint8_t> rest(static_cast<std::size_t>(block.length - format::header_size));  // not too long
  if (!source_.read(offset + format::header_size, rest.data(), rest.size()))
    return Failure{here(offset) + ": cannot read"};
  for (std::size_t index = 0; index < block.links.size(); ++index)
    block.links[index] = load<std::uint64_t>(&rest[8 * index]);
  block.data.assign(rest.begin() + static_cast<std::ptrdiff_t>(8 * block.links.size()), rest.end());
  return read;
}

Result<Block> BlockReader::read_shared(std::uint64_t offset, std::initializer_list<std::string_view> ids,
                                       std::string_view via) {
  if (const auto found = shared_.find(offset); found != shared_.end()) {
    if (std::none_of(ids.begin(), ids.end(), [&](std::string_view id) { return id == found->second.id; }))
      return Failure{here(offset) + ": expected " + expected_ids(ids) + " (" + std::string{via} + "), found ##" +
                     found->second.id};
    return found->second;
  }
  auto block = read(offset, ids, via);
  if (block) shared_.emplace(offset, block.value());
  return block;
}

Result<Block> BlockReader::read_data_header(std::uint64_t offset, std::string_view via) {
  const std::uint64_t size = source_.size();
  if (offset >= format::id::size && offset <= size && size - offset >= format::header_size) {
    // The length may be one the writer had not yet updated: checked by claim_data() once recovered.
    std::uint8_t id[4];
    if (source_.read(offset, id, 4) && id[2] == 'D' && id[3] == 'T') {
      std::uint8_t bytes[format::header_size];
      if (!source_.read(offset, bytes, sizeof bytes)) return Failure{here(offset) + ": cannot read"};
      Block block{.offset = offset, .id = "DT", .length = load<std::uint64_t>(bytes + format::length_field)};
      if (id[0] == '#' && id[1] == '#' && load<std::uint64_t>(bytes + format::link_count_field) == 0) return block;
    }
  }
  return header(offset, {"DT"}, via);  // for its message
}

Status BlockReader::claim_data(const Block& block) {
  const std::uint64_t size = source_.size();
  if (block.length < format::header_size || block.length > size - block.offset)
    return Failure{here(block.offset) + ": ##DT block of length " + std::to_string(block.length) +
                   " runs past the end of the file (" + std::to_string(size) + " bytes)"};
  return claim(block.offset, block.length, "##DT block");
}

std::uint64_t BlockReader::next_block_after(std::uint64_t offset) const {
  const auto after = claimed_.upper_bound(offset);
  return after == claimed_.end() ? source_.size() : after->first;
}

Result<std::string> BlockReader::text(std::uint64_t offset, std::string_view via) {
  if (offset == 0) return std::string{};
  if (const auto found = texts_.find(offset); found != texts_.end()) return found->second;
  auto block = read_shared(offset, {"TX", "MD"}, via);
  if (!block) return Failure{block.error()};
  const std::vector<std::uint8_t>& data = block.value().data;
  std::string text{data.begin(), std::find(data.begin(), data.end(), std::uint8_t{0})};
  if (block.value().id == "MD") text = text_of_xml(text);
  texts_.emplace(offset, text);
  return text;
}

}  // namespace duet::mdf4
