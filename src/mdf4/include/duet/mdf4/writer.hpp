#pragma once
// Writes a sorted ASAM MDF 4.20 file as the samples arrive, in bounded memory: each group's records are buffered up to
// a fragment and appended as a data block; finalise() patches the sample counts and marks the file finalised. A
// writer that dies before leaves an unfinalised file whose appended fragments the reader recovers (docs/MDF4.md).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <variant>

#include "duet/mdf4/spec.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4 {

// One channel's sample in its exact type; std::monostate is a missing sample (its invalidation bit is set).
using Value = std::variant<std::monostate, bool, std::uint8_t, std::uint16_t, std::uint32_t, std::uint64_t, std::int8_t,
                           std::int16_t, std::int32_t, std::int64_t, float, double>;

struct WriterOptions {
  // A group's records are appended to the file once this many bytes of them are buffered (and by flush()): the
  // memory a group takes, and what a crash may lose of it.
  std::size_t fragment_bytes = std::size_t{64} * 1024;
};

class Writer {
 public:
  // Creates (or truncates) `path` and writes every group's description; the file is unfinalised until finalise().
  static Result<Writer> create(const std::filesystem::path& path, const FileSpec& spec, WriterOptions options = {});

  Writer(Writer&&) noexcept;
  Writer& operator=(Writer&&) noexcept;
  ~Writer();  // finalises if finalise() was not called, ignoring errors (the file then stays recoverable)

  // One sample of group `group`: its time (seconds since the start, finite, not before the group's previous sample)
  // and one value per channel in the order of the group's channels, a vector's elements in order.
  Status append(std::size_t group, double time_s, std::span<const Value> values);
  // Every buffered record to the file.
  Status flush();
  // The buffered records, the sample counts, and the file marked finalised. Nothing may be appended after.
  Status finalise();

 private:
  struct State;
  explicit Writer(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace duet::mdf4
