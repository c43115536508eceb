#include "data_stream.hpp"

#include <algorithm>
#include <cstring>

namespace duet::mdf4 {
namespace {
constexpr std::size_t chunk_bytes = 1 << 20;
}

bool DataStream::refill(std::size_t wanted) {
  // Keep the unread bytes, then read whole chunks until `wanted` are there or the pieces end.
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
  start_ = 0;
  while (buffer_.size() < wanted && piece_ < pieces_.size()) {
    const DataPiece& piece = pieces_[piece_];
    // At most a chunk or what is still wanted, which are sizes in memory.
    const auto take = static_cast<std::size_t>(
        std::min<std::uint64_t>(piece.size - piece_used_, std::max(chunk_bytes, wanted - buffer_.size())));
    const std::size_t at = buffer_.size();
    buffer_.resize(at + take);
    if (!source_.read(piece.offset + piece_used_, buffer_.data() + at, take)) {
      failed_ = true;
      return false;
    }
    piece_used_ += take;
    if (piece_used_ == piece.size) {
      ++piece_;
      piece_used_ = 0;
    }
  }
  return buffer_.size() >= wanted;
}

std::span<const std::uint8_t> DataStream::next(std::size_t count) {
  if (buffer_.size() - start_ < count && !refill(count)) return {};
  const std::span<const std::uint8_t> bytes{buffer_.data() + start_, count};
  start_ += count;
  return bytes;
}

}  // namespace duet::mdf4
