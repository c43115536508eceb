#pragma once
// A data group's records as one stream over its data blocks (a DT, or the DTs of a DL chain), read in chunks so that
// memory stays bounded whatever the file's size; a record may span two blocks.

#include <cstdint>
#include <span>
#include <vector>

#include "byte_source.hpp"

namespace duet::mdf4 {

struct DataPiece {
  std::uint64_t offset = 0;  // of the record bytes in the file
  std::uint64_t size = 0;
};

class DataStream {
 public:
  DataStream(const ByteSource& source, const std::vector<DataPiece>& pieces) : source_(source), pieces_(pieces) {}
  // The next `count` bytes, valid until the next call; empty if the stream holds fewer (or a read failed: failed()).
  std::span<const std::uint8_t> next(std::size_t count);
  [[nodiscard]] bool failed() const { return failed_; }

 private:
  bool refill(std::size_t wanted);

  const ByteSource& source_;
  const std::vector<DataPiece>& pieces_;
  std::size_t piece_ = 0;
  std::uint64_t piece_used_ = 0;
  std::vector<std::uint8_t> buffer_;
  std::size_t start_ = 0;
  bool failed_ = false;
};

}  // namespace duet::mdf4
