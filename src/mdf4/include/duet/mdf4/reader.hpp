#pragma once
// Reads sorted and unsorted ASAM MDF 4.x files (4.00 to 4.2x) of fixed-length numeric channels: what duet's writer
// writes and what other writers commonly do (docs/MDF4.md, "Reading"). An unfinalised file is recovered from what
// reached the disk. A file that is not MDF, or is damaged, gives an error naming the block's offset and the problem.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::mdf4 {

// A stored value as it is in the file, bit for bit: unsigned and signed integers widened, floats as they are.
using Number = std::variant<std::uint64_t, std::int64_t, float, double>;
double to_double(const Number& number);

struct Conversion {
  enum class Kind { identity, linear, value_to_text, unsupported };
  Kind kind = Kind::identity;
  std::uint8_t cc_type = 0;                           // MDF's conversion type code
  double factor = 1, offset = 0;                      // linear: physical = factor * stored + offset
  std::vector<std::pair<double, std::string>> texts;  // value_to_text: key, text
  std::string default_text;
};

// What a channel's physical value is: a number, or a text from a value-to-text conversion.
using Physical = std::variant<Number, double, std::string>;

struct ChannelInfo {
  std::string name, unit, comment;
  enum class Role { value, master, virtual_master } role = Role::value;
  // Decoded: integers (unsigned, signed) of 1 to 64 bits and floats of 32 or 64 bits, little- or big-endian.
  // Others (strings, byte arrays, variable length) are listed but not decoded.
  bool decoded = true;
  std::uint8_t data_type = 0;  // MDF's data type code
  std::uint32_t byte_offset = 0, bit_offset = 0, bit_count = 0;
  std::optional<std::uint32_t> invalidation_bit;
  Conversion conversion;
  std::uint64_t block_offset = 0;  // the CN block
};

struct GroupInfo {
  std::string name, comment;  // the acquisition name and comment
  std::vector<ChannelInfo> channels;
  std::optional<std::size_t> master;  // the time (or other master) channel
  std::uint64_t samples = 0;
  std::uint32_t data_bytes = 0, invalidation_bytes = 0;
  std::uint64_t record_id = 0;     // in an unsorted data group
  std::uint64_t block_offset = 0;  // the CG block

  // A record's bytes (the reader refuses groups whose records are implausibly long, so this fits in memory).
  [[nodiscard]] std::size_t record_bytes() const { return std::size_t{data_bytes} + invalidation_bytes; }
};

struct FileInfo {
  std::string version;  // "4.20"
  std::uint16_t version_number = 0;
  std::string program;
  bool finalised = true;
  std::uint16_t unfinalised_flags = 0;  // what the writer had not yet updated (recovered on reading)
  std::uint64_t start_time_ns = 0;
  std::vector<std::string> history;  // the tools named in the file history (<tool_id> <tool_version>, or the text)
  std::vector<GroupInfo> groups;     // one per channel group, in the order of the data groups
};

// One record of a group, decoded on request.
class Record {
 public:
  Record(const GroupInfo& group, std::span<const std::uint8_t> bytes, std::uint64_t index)
      : group_(&group), bytes_(bytes), index_(index) {}
  // Precondition: channel < channels.size(). A channel that is not decoded reads 0.
  [[nodiscard]] Number value(std::size_t index) const;
  [[nodiscard]] bool valid(std::size_t index) const;
  [[nodiscard]] Physical physical(std::size_t index) const;
  // The master's physical value (seconds for a time master); NaN if the group has none.
  [[nodiscard]] double time() const;
  [[nodiscard]] std::uint64_t index() const { return index_; }

 private:
  const GroupInfo* group_;
  std::span<const std::uint8_t> bytes_;  // without the record id
  std::uint64_t index_;
};

// A group's records one at a time, in order, so that several groups can be read side by side.
class RecordCursor {
 public:
  RecordCursor(RecordCursor&&) noexcept;
  RecordCursor& operator=(RecordCursor&&) noexcept;
  ~RecordCursor();
  // The next record, valid until the next call; none at the end, or if reading failed (error() then says why).
  std::optional<Record> next();
  [[nodiscard]] const std::string& error() const;

 private:
  friend class Reader;
  struct State;
  explicit RecordCursor(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

class Reader {
 public:
  static Result<Reader> open(const std::filesystem::path& path);
  // `name` stands for the file in messages.
  static Result<Reader> from_bytes(std::vector<std::uint8_t> bytes, std::string name = "(memory)");

  Reader(Reader&&) noexcept;
  Reader& operator=(Reader&&) noexcept;
  ~Reader();

  [[nodiscard]] const FileInfo& info() const;
  // Precondition: group < info().groups.size().
  [[nodiscard]] RecordCursor records(std::size_t group) const;
  // Every record of `group` in order, through `visit`; fails naming the block if the data is damaged.
  Status for_each_record(std::size_t group, const std::function<void(const Record&)>& visit) const;
  // The first and last master values, if the group has a master and samples.
  [[nodiscard]] Result<std::optional<std::pair<double, double>>> time_span(std::size_t group) const;

 private:
  struct State;
  explicit Reader(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace duet::mdf4
