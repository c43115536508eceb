// Files that are not MDF, or are damaged: each gives an error naming the place and the problem; none crashes or
// hangs (the sanitizers of the host build watch the first; ctest's timeout the second).
#include <gtest/gtest.h>

#include <functional>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/writer.hpp"
#include "hand_made_file.hpp"
#include "test_files.hpp"

namespace duet::mdf4 {
namespace {

using testing::HandMadeFile;
using testing::TemporaryFile;

// A valid file of duet's writer with two fragments of data, whose bytes each case damages.
std::vector<std::uint8_t> valid_file() {
  const TemporaryFile file{"valid.mf4"};
  {
    auto writer = Writer::create(
        file.path(),
        FileSpec{.groups = {{.name = "g", .comment = "", .channels = {{.name = "n", .type = ValueType::u16}}}}},
        WriterOptions{.fragment_bytes = 16});
    for (std::uint16_t sample = 0; sample < 4; ++sample)
      (void)writer.value().append(0, sample, std::vector<Value>{sample});
  }
  return file.bytes();
}

template <typename T>
T get(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}
template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

// A link of the valid file, which is small: a position in its bytes.
std::size_t position(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return static_cast<std::size_t>(get<std::uint64_t>(bytes, at));
}

// Where the valid file's blocks are, found through its links (offsets of the format's tables).
struct Places {
  explicit Places(const std::vector<std::uint8_t>& bytes)
      : dg(position(bytes, 64 + 24)),
        fh(position(bytes, 64 + 32)),
        cg(position(bytes, dg + 32)),
        dl(position(bytes, dg + 40)),
        time(position(bytes, cg + 32)),
        value(position(bytes, time + 24)),
        dt(position(bytes, dl + 32)),
        next_dl(position(bytes, dl + 24)) {}
  std::size_t dg, fh, cg, dl, time, value, dt, next_dl;
};

struct Case {
  const char* name;
  std::function<void(std::vector<std::uint8_t>&, const Places&)> damage;
  const char* message;  // what the error says, after the file's name
};

// The error for the damaged file, opening it and reading every record.
std::string error_of(std::vector<std::uint8_t> bytes) {
  auto reader = Reader::from_bytes(std::move(bytes), "bad.mf4");
  if (!reader) return reader.error();
  for (std::size_t group = 0; group < reader.value().info().groups.size(); ++group) {
    Status read = reader.value().for_each_record(group, [](const Record& record) { (void)record.time(); });
    if (!read) return read.error();
  }
  return "(no error)";
}

TEST(Mdf4Malformed, TheValidFileReads) {
  auto reader = Reader::from_bytes(valid_file());
  ASSERT_TRUE(reader) << reader.error();
  EXPECT_EQ(reader.value().info().groups[0].samples, 4u);
  EXPECT_NE(Places{valid_file()}.next_dl, 0u);  // the cases below need two fragments
}

TEST(Mdf4Malformed, EachDamageIsNamed) {
  const std::vector<Case> cases = {
      {"empty", [](auto& bytes, const Places&) { bytes.clear(); },
       ": not an MDF file (0 bytes, fewer than the 64 of an MDF identification block)"},
      {"truncated in the identification", [](auto& bytes, const Places&) { bytes.resize(40); },
       ": not an MDF file (40 bytes, fewer than the 64 of an MDF identification block)"},
      {"not MDF", [](auto& bytes, const Places&) { std::memcpy(bytes.data(), "PK\3\4zip ", 8); },
       ": not an MDF file (it starts with \"PK\3\4zip\", not \"MDF\")"},
      {"MDF 3", [](auto& bytes, const Places&) { put<std::uint16_t>(bytes, 28, 330); },
       ": MDF version 4.20 (330); duet reads MDF 4 only"},
      {"truncated after the identification", [](auto& bytes, const Places&) { bytes.resize(64); },
       ": the identification block links to 0x40, past the end of the file (64 bytes)"},
      {"no header", [](auto& bytes, const Places&) { std::memcpy(bytes.data() + 64, "##XX", 4); },
       ": at 0x40: expected ##HD (the identification block), found \"##XX\""},
      {"truncated in the data", [](auto& bytes, const Places& at) { bytes.resize(at.dt + 30); },
       "links to"},  // the block list beyond the end
      {"a link past the end", [](auto& bytes, const Places&) { put<std::uint64_t>(bytes, 64 + 24, 1ull << 40); },
       ": the first ##DG of the ##HD links to 0x10000000000, past the end of the file"},
      {"a link into the identification", [](auto& bytes, const Places&) { put<std::uint64_t>(bytes, 64 + 24, 8); },
       ": the first ##DG of the ##HD links to 0x8, inside the identification block"},
      {"a link to the wrong block",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.dg + 32, at.time); },
       "expected ##CG (the first ##CG of the ##DG at"},
      {"a length beyond the file",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.cg + 8, 1ull << 32); },
       ": ##CG block of length 4294967296 runs past the end of the file"},
      {"a length shorter than the links",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.time + 8, 40); },
       ": ##CN block of length 40 cannot hold its 8 links"},
      {"a channel chain looping to itself",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.value + 24, at.time); },
       " is reached a second time (a loop in the links, or a block linked twice)"},
      {"a data group chain looping",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.dg + 24, at.dg); },
       " is reached a second time"},
      {"a data list looping", [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.next_dl + 24, at.dl); },
       " is reached a second time"},
      {"a block over the next", [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.time + 8, 200); },
       "lies inside the block at"},
      {"a data block longer than the file",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.dt + 8, 1ull << 50); },
       ": ##DT block of length 1125899906842624 runs past the end of the file"},
      {"more samples than data", [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.cg + 80, 1000); },
       ": ##CG block counts 1000 samples of 11 bytes; its data holds 44 bytes"},
      {"a value outside the record",
       [](auto& bytes, const Places& at) { put<std::uint32_t>(bytes, at.value + 92, 20); },
       "'n': its value (bytes 20 to 21) lies outside the record's 10 data bytes"},
      {"an invalidation bit outside the record",
       [](auto& bytes, const Places& at) { put<std::uint32_t>(bytes, at.value + 104, 9); },
       "'n': invalidation bit 9 lies outside the record's 1 invalidation bytes"},
      {"records of no bytes",
       [](auto& bytes, const Places& at) {
         put<std::uint32_t>(bytes, at.cg + 96, 0);
         put<std::uint32_t>(bytes, at.cg + 100, 0);
       },
       ": ##CG block: its records have no bytes"},
      {"records longer than a reader allocates",
       [](auto& bytes, const Places& at) { put<std::uint32_t>(bytes, at.cg + 96, 0xFFFF'FFF0U); },
       ": ##CG block: its records of 4294967281 bytes are implausibly long"},
      {"a bad record id size", [](auto& bytes, const Places& at) { bytes[at.dg + 56] = 3; },
       ": ##DG block's record id size 3 is not 0, 1, 2, 4 or 8"},
      {"a list counting more blocks than it links",
       [](auto& bytes, const Places& at) { put<std::uint32_t>(bytes, at.dl + 44, 5); },
       ": ##DL block lists 5 data blocks in 1 links"},
      {"a NIL data link in a finalised list",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.dl + 32, 0); },
       ": ##DL block's data link 0 is NIL"},
      {"a name that is not text",
       [](auto& bytes, const Places& at) { put<std::uint64_t>(bytes, at.value + 40, at.cg); },
       "expected ##TX or ##MD (the name of the ##CN at"},
      {"a variable-length channel group", [](auto& bytes, const Places& at) { bytes[at.cg + 88] = 1; },
       ": ##CG block: variable-length (VLSD) channel groups are not supported"},
      {"compressed data", [](auto& bytes, const Places& at) { std::memcpy(bytes.data() + at.dt, "##DZ", 4); },
       ": compressed data (##DZ) is not supported"},
      {"two masters", [](auto& bytes, const Places& at) { bytes[at.value + 88] = 2; },
       ": ##CN block 'n' is a second master channel of its group"},
  };
  ASSERT_GE(cases.size(), 20u);
  const std::vector<std::uint8_t> valid = valid_file();
  const Places places{valid};
  for (const Case& damaged : cases) {
    std::vector<std::uint8_t> bytes = valid;
    damaged.damage(bytes, places);
    const std::string error = error_of(bytes);
    EXPECT_EQ(error.rfind("bad.mf4", 0), 0u) << damaged.name << ": " << error;
    EXPECT_NE(error.find(damaged.message), std::string::npos) << damaged.name << ": " << error;
  }
}

// Unsorted records whose id no group has, in a finalised file.
TEST(Mdf4Malformed, AnUnknownRecordId) {
  HandMadeFile file;
  const std::size_t header = file.header();
  const std::size_t group = file.data_group(1);
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(1, 1, 1, 0);
  file.link(group, 1, channel_group);
  file.link(channel_group, 1, file.channel("n", 0, 0, 0, 8));
  file.link(group, 2, file.data_block({1, 10, 7, 11}));
  EXPECT_NE(error_of(file.bytes).find(": ##DG data byte 2 has record id 7, which no ##CG of it has"), std::string::npos)
      << error_of(file.bytes);
}

// Every prefix of a valid file, and every byte of it flipped: an error or a file, never a crash.
TEST(Mdf4Malformed, EveryTruncationAndEveryFlippedByte) {
  const std::vector<std::uint8_t> valid = valid_file();
  for (std::size_t size = 0; size < valid.size(); ++size)
    (void)error_of({valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(size)});
  for (std::size_t at = 0; at < valid.size(); ++at) {
    std::vector<std::uint8_t> bytes = valid;
    bytes[at] = static_cast<std::uint8_t>(bytes[at] ^ 0xA5);
    (void)error_of(bytes);
  }
}

}  // namespace
}  // namespace duet::mdf4
