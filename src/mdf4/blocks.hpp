#pragma once
// Blocks read from an MDF file with every check a damaged file needs: the id expected, the length within the file,
// and no block overlapping another, which also finds loops in the links and bounds the work to the file's size.

#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "byte_source.hpp"
#include "bytes.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4 {

struct Block {
  std::uint64_t offset = 0;
  std::string id;  // "DG", "CN", ... (without "##")
  std::uint64_t length = 0;
  std::vector<std::uint64_t> links;
  std::vector<std::uint8_t> data;  // the data section (empty for a DT, whose records are read as a stream)

  [[nodiscard]] std::uint64_t link(std::size_t index) const { return index < links.size() ? links[index] : 0; }
  // A field of the data section; 0 beyond its end (callers check data.size() where a field is required).
  template <typename T>
  [[nodiscard]] T field(std::uint64_t at) const {
    return at + sizeof(T) <= data.size() ? load<T>(data.data() + at) : T{};
  }
};

class BlockReader {
 public:
  explicit BlockReader(const ByteSource& source) : source_(source) {}

  // The block at `offset`, reached through `via` (e.g. "the first DG of the HD"), one of `ids`. Fails if it is not
  // there, or it was already read (a loop, or two owners of one block), or it overlaps another block.
  Result<Block> read(std::uint64_t offset, std::initializer_list<std::string_view> ids, std::string_view via);
  // The same for blocks that may be shared (texts and conversions): a second read returns the first.
  Result<Block> read_shared(std::uint64_t offset, std::initializer_list<std::string_view> ids, std::string_view via);
  // A DT's header only; its records span `length - 24` bytes, claimed by claim_data() once the length is known.
  Result<Block> read_data_header(std::uint64_t offset, std::string_view via);
  Status claim_data(const Block& block);
  // The text of a TX block, or the <TX> of an MD block's XML (its XML if it has none); "" for NIL.
  Result<std::string> text(std::uint64_t offset, std::string_view via);
  // The first block after `offset` that was read, or the file's end.
  [[nodiscard]] std::uint64_t next_block_after(std::uint64_t offset) const;

  [[nodiscard]] std::string here(std::uint64_t offset) const;  // "FILE: at 0x1A0" for messages
  [[nodiscard]] const ByteSource& source() const { return source_; }

 private:
  Result<Block> header(std::uint64_t offset, std::initializer_list<std::string_view> ids, std::string_view via);
  Status claim(std::uint64_t offset, std::uint64_t length, std::string_view what);

  const ByteSource& source_;
  std::map<std::uint64_t, std::uint64_t> claimed_;  // offset -> end of every block read
  std::map<std::uint64_t, Block> shared_;
  std::map<std::uint64_t, std::string> texts_;
};

std::string hex(std::uint64_t value);

}  // namespace duet::mdf4
