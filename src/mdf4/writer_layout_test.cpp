// The writer's blocks byte by byte, at the offsets of the format's tables (docs/MDF4.md, "Layout"): a field written at
// a wrong offset, of a wrong width, or a link left dangling fails here.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "duet/mdf4/writer.hpp"
#include "duet/version.hpp"
#include "test_files.hpp"

namespace duet::mdf4 {
namespace {

using testing::TemporaryFile;

class WrittenFile {
 public:
  explicit WrittenFile(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}
  template <typename T>
  [[nodiscard]] [[nodiscard]] [[nodiscard]] [[nodiscard]] [[nodiscard]] [[nodiscard]] T at(std::uint64_t offset) const {
    EXPECT_LE(offset + sizeof(T), bytes_.size());
    T value{};
    if (offset + sizeof(T) <= bytes_.size()) std::memcpy(&value, bytes_.data() + offset, sizeof value);
    return value;
  }
  [[nodiscard]] std::string text(std::uint64_t offset, std::size_t size) const {
    return offset + size <= bytes_.size() ? std::string{bytes_.begin() + static_cast<std::ptrdiff_t>(offset),
                                                        bytes_.begin() + static_cast<std::ptrdiff_t>(offset + size)}
                                          : std::string{};
  }
  // A block's common header: its id, zero reserved bytes, its length and link count; 8-byte aligned.
  void expect_block(std::uint64_t offset, const std::string& id, std::uint64_t length, std::uint64_t links) const {
    SCOPED_TRACE(id + " at " + std::to_string(offset));
    EXPECT_EQ(offset % 8, 0u);
    EXPECT_EQ(text(offset, 4), id);
    EXPECT_EQ(at<std::uint32_t>(offset + 4), 0u);
    EXPECT_EQ(at<std::uint64_t>(offset + 8), length);
    EXPECT_EQ(at<std::uint64_t>(offset + 16), links);
  }
  // A TX or MD block's text: zero-terminated, the length a multiple of 8 with zeros after the text.
  [[nodiscard]] std::string block_text(std::uint64_t offset, const std::string& id = "##TX") const {
    const auto length = at<std::uint64_t>(offset + 8);
    expect_block(offset, id, length, 0);
    EXPECT_EQ(length % 8, 0u);
    const std::string content = text(offset + 24, static_cast<std::size_t>(length - 24));
    const std::size_t end = content.find('\0');
    EXPECT_NE(end, std::string::npos);
    EXPECT_EQ(content.find_first_not_of('\0', end), std::string::npos);
    return content.substr(0, end);
  }
  [[nodiscard]] std::size_t size() const { return bytes_.size(); }

 private:
  std::vector<std::uint8_t> bytes_;
};

FileSpec one_group() {
  return FileSpec{.groups = {{.name = "rate 1",
                              .comment = "the base rate",
                              .channels = {{.name = "speed",
                                            .type = ValueType::i16,
                                            .unit = "rad/s",
                                            .comment = "wheel speed",
                                            .conversion = Linear{.factor = 0.25, .offset = -3}}}}},
                  .start_time_ns = 0x0123456789ABCDEF};
}

WrittenFile written(const TemporaryFile& file, bool finalise) {
  auto writer = Writer::create(file.path(), one_group());
  EXPECT_TRUE(writer);
  EXPECT_TRUE(writer.value().append(0, 0.5, std::vector<Value>{std::int16_t{-2}}));
  EXPECT_TRUE(writer.value().append(0, 1.5, std::vector<Value>{Value{}}));
  if (finalise) {
    EXPECT_TRUE(writer.value().finalise());
    return WrittenFile{file.bytes()};
  }
  EXPECT_TRUE(writer.value().flush());
  WrittenFile before{file.bytes()};
  EXPECT_TRUE(writer.value().finalise());
  return before;
}

TEST(Mdf4Layout, IdentificationBlock) {
  const TemporaryFile file{"id.mf4"};
  const WrittenFile bytes = written(file, true);
  EXPECT_EQ(bytes.text(0, 8), "MDF     ");
  EXPECT_EQ(bytes.text(8, 8), "4.20    ");
  EXPECT_EQ(bytes.text(16, 8), "duet    ");
  EXPECT_EQ(bytes.at<std::uint32_t>(24), 0u);
  EXPECT_EQ(bytes.at<std::uint16_t>(28), 420);
  for (std::uint64_t reserved = 30; reserved < 60; ++reserved) EXPECT_EQ(bytes.at<std::uint8_t>(reserved), 0);
  EXPECT_EQ(bytes.at<std::uint16_t>(60), 0);  // finalised: nothing left to update
  EXPECT_EQ(bytes.at<std::uint16_t>(62), 0);
  EXPECT_EQ(bytes.size() % 8, 0u);
}

TEST(Mdf4Layout, AnUnfinalisedFileSaysSoAndCountsNothingYet) {
  const TemporaryFile file{"unfinalised.mf4"};
  const WrittenFile bytes = written(file, false);
  EXPECT_EQ(bytes.text(0, 8), "UnFinMF ");
  EXPECT_EQ(bytes.at<std::uint16_t>(60), 0x01);  // the cycle counts are not up to date
  const auto group = bytes.at<std::uint64_t>(64 + 24);
  const auto channel_group = bytes.at<std::uint64_t>(group + 32);
  EXPECT_EQ(bytes.at<std::uint64_t>(channel_group + 80), 0u);
  EXPECT_NE(bytes.at<std::uint64_t>(group + 40), 0u);  // but the flushed data is linked
}

TEST(Mdf4Layout, HeaderAndFileHistory) {
  const TemporaryFile file{"hd.mf4"};
  const WrittenFile bytes = written(file, true);
  bytes.expect_block(64, "##HD", 104, 6);
  EXPECT_NE(bytes.at<std::uint64_t>(64 + 24), 0u);  // first DG
  const auto history = bytes.at<std::uint64_t>(64 + 32);
  EXPECT_EQ(bytes.at<std::uint64_t>(64 + 40), 0u);  // channel hierarchy
  EXPECT_EQ(bytes.at<std::uint64_t>(64 + 48), 0u);  // attachments
  EXPECT_EQ(bytes.at<std::uint64_t>(64 + 56), 0u);  // events
  EXPECT_EQ(bytes.at<std::uint64_t>(64 + 64), 0u);  // no comment
  EXPECT_EQ(bytes.at<std::uint64_t>(64 + 72), 0x0123456789ABCDEFu);
  EXPECT_EQ(bytes.at<std::int16_t>(64 + 80), 0);
  EXPECT_EQ(bytes.at<std::int16_t>(64 + 82), 0);
  EXPECT_EQ(bytes.at<std::uint8_t>(64 + 84), 0);  // UTC, no offsets
  EXPECT_EQ(bytes.at<double>(64 + 88), 0.0);
  EXPECT_EQ(bytes.at<double>(64 + 96), 0.0);

  bytes.expect_block(history, "##FH", 56, 2);
  EXPECT_EQ(bytes.at<std::uint64_t>(history + 24), 0u);                          // no next
  EXPECT_GT(bytes.at<std::uint64_t>(history + 40), 1'700'000'000'000'000'000u);  // written after 2023
  EXPECT_EQ(bytes.at<std::uint8_t>(history + 52), 0);
  const std::string comment = bytes.block_text(bytes.at<std::uint64_t>(history + 32), "##MD");
  EXPECT_EQ(comment.rfind("<FHcomment", 0), 0u) << comment;
  EXPECT_NE(comment.find("<TX>"), std::string::npos);
  EXPECT_NE(comment.find("<tool_id>duet</tool_id>"), std::string::npos);
  EXPECT_NE(comment.find("<tool_vendor>"), std::string::npos);
  EXPECT_NE(comment.find("<tool_version>" + std::string{duet::version} + "</tool_version>"), std::string::npos);
}

TEST(Mdf4Layout, DataGroupChannelGroupChannelsConversionAndData) {
  const TemporaryFile file{"groups.mf4"};
  const WrittenFile bytes = written(file, true);
  const auto group = bytes.at<std::uint64_t>(64 + 24);
  bytes.expect_block(group, "##DG", 64, 4);
  EXPECT_EQ(bytes.at<std::uint64_t>(group + 24), 0u);  // the only DG
  const auto channel_group = bytes.at<std::uint64_t>(group + 32);
  const auto data = bytes.at<std::uint64_t>(group + 40);
  EXPECT_EQ(bytes.at<std::uint64_t>(group + 48), 0u);
  EXPECT_EQ(bytes.at<std::uint8_t>(group + 56), 0);  // sorted: no record ids

  bytes.expect_block(channel_group, "##CG", 104, 6);
  EXPECT_EQ(bytes.at<std::uint64_t>(channel_group + 24), 0u);
  const auto time = bytes.at<std::uint64_t>(channel_group + 32);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(channel_group + 40)), "rate 1");
  EXPECT_EQ(bytes.at<std::uint64_t>(channel_group + 48), 0u);
  EXPECT_EQ(bytes.at<std::uint64_t>(channel_group + 56), 0u);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(channel_group + 64)), "the base rate");
  EXPECT_EQ(bytes.at<std::uint64_t>(channel_group + 80), 2u);  // samples
  EXPECT_EQ(bytes.at<std::uint16_t>(channel_group + 88), 0);
  EXPECT_EQ(bytes.at<std::uint16_t>(channel_group + 90), 0);
  EXPECT_EQ(bytes.at<std::uint32_t>(channel_group + 96), 10u);  // f64 time, i16 speed
  EXPECT_EQ(bytes.at<std::uint32_t>(channel_group + 100), 1u);  // one invalidation byte

  bytes.expect_block(time, "##CN", 160, 8);
  const auto speed = bytes.at<std::uint64_t>(time + 24);
  EXPECT_EQ(bytes.at<std::uint64_t>(time + 32), 0u);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(time + 40)), "time");
  EXPECT_EQ(bytes.at<std::uint64_t>(time + 48), 0u);
  EXPECT_EQ(bytes.at<std::uint64_t>(time + 56), 0u);  // no conversion
  EXPECT_EQ(bytes.at<std::uint64_t>(time + 64), 0u);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(time + 72)), "s");
  EXPECT_EQ(bytes.at<std::uint64_t>(time + 80), 0u);
  EXPECT_EQ(bytes.at<std::uint8_t>(time + 88), 2);  // master
  EXPECT_EQ(bytes.at<std::uint8_t>(time + 89), 1);  // time
  EXPECT_EQ(bytes.at<std::uint8_t>(time + 90), 4);  // IEEE float, little-endian
  EXPECT_EQ(bytes.at<std::uint8_t>(time + 91), 0);
  EXPECT_EQ(bytes.at<std::uint32_t>(time + 92), 0u);
  EXPECT_EQ(bytes.at<std::uint32_t>(time + 96), 64u);
  EXPECT_EQ(bytes.at<std::uint32_t>(time + 100), 0u);  // no invalidation bit

  bytes.expect_block(speed, "##CN", 160, 8);
  EXPECT_EQ(bytes.at<std::uint64_t>(speed + 24), 0u);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(speed + 40)), "speed");
  const auto conversion = bytes.at<std::uint64_t>(speed + 56);
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(speed + 72)), "rad/s");
  EXPECT_EQ(bytes.block_text(bytes.at<std::uint64_t>(speed + 80)), "wheel speed");
  EXPECT_EQ(bytes.at<std::uint8_t>(speed + 88), 0);
  EXPECT_EQ(bytes.at<std::uint8_t>(speed + 89), 0);
  EXPECT_EQ(bytes.at<std::uint8_t>(speed + 90), 2);  // signed, little-endian
  EXPECT_EQ(bytes.at<std::uint32_t>(speed + 92), 8u);
  EXPECT_EQ(bytes.at<std::uint32_t>(speed + 96), 16u);
  EXPECT_EQ(bytes.at<std::uint32_t>(speed + 100), 2u);  // the invalidation bit is valid
  EXPECT_EQ(bytes.at<std::uint32_t>(speed + 104), 0u);  // and is bit 0
  EXPECT_EQ(bytes.at<std::uint16_t>(speed + 110), 0);   // no attachments

  bytes.expect_block(conversion, "##CC", 96, 4);
  for (unsigned link = 0; link < 4; ++link)
    EXPECT_EQ(bytes.at<std::uint64_t>(conversion + 24 + 8 * std::uint64_t{link}), 0u);
  EXPECT_EQ(bytes.at<std::uint8_t>(conversion + 56), 1);  // linear
  EXPECT_EQ(bytes.at<std::uint16_t>(conversion + 60), 0);
  EXPECT_EQ(bytes.at<std::uint16_t>(conversion + 62), 2);
  EXPECT_EQ(bytes.at<double>(conversion + 80), -3.0);  // P1, the offset
  EXPECT_EQ(bytes.at<double>(conversion + 88), 0.25);  // P2, the factor

  // The data: a list of one data block, with the records (time, speed, invalidation byte).
  bytes.expect_block(data, "##DL", 56, 2);
  EXPECT_EQ(bytes.at<std::uint64_t>(data + 24), 0u);
  const auto records = bytes.at<std::uint64_t>(data + 32);
  EXPECT_EQ(bytes.at<std::uint8_t>(data + 40), 0);  // offsets follow
  EXPECT_EQ(bytes.at<std::uint32_t>(data + 44), 1u);
  EXPECT_EQ(bytes.at<std::uint64_t>(data + 48), 0u);
  bytes.expect_block(records, "##DT", 24 + 2 * 11, 0);
  EXPECT_EQ(bytes.at<double>(records + 24), 0.5);
  EXPECT_EQ(bytes.at<std::int16_t>(records + 32), -2);
  EXPECT_EQ(bytes.at<std::uint8_t>(records + 34), 0);
  EXPECT_EQ(bytes.at<double>(records + 35), 1.5);
  EXPECT_EQ(bytes.at<std::int16_t>(records + 43), 0);
  EXPECT_EQ(bytes.at<std::uint8_t>(records + 45), 1);  // missing
  EXPECT_EQ(bytes.at<std::uint8_t>(records + 46), 0);  // alignment fill
  EXPECT_LT(records, data);                            // the list follows the block it lists
}

// A file killed before any data ends with its description: never with a channel block, which a recovering reader
// may read past its end. Here every text of the last group's channel is shared with the first group's.
TEST(Mdf4Layout, TheDescriptionEndsWithAnotherBlockThanAChannel) {
  const TemporaryFile file{"description.mf4"};
  const GroupSpec group{.name = "g", .comment = "", .channels = {{.name = "n", .type = ValueType::u8}}};
  auto writer = Writer::create(file.path(), FileSpec{.groups = {group, group}});
  ASSERT_TRUE(writer);
  const WrittenFile bytes{file.bytes()};
  std::uint64_t last = 64;
  for (std::uint64_t block = 64; block < bytes.size(); block = (block + bytes.at<std::uint64_t>(block + 8) + 7) / 8 * 8)
    last = block;
  EXPECT_NE(bytes.text(last, 4), "##CN");
  EXPECT_EQ(bytes.text(last, 4), "##MD");  // the history's XML
}

// What bounds the writer's memory: no data block larger than a fragment and a record, each listed by its own DL,
// chained in order, the offsets counting the group's bytes before it.
TEST(Mdf4Layout, DataInBoundedFragmentsEachListedInTheChain) {
  const TemporaryFile file{"fragments.mf4"};
  {
    auto writer = Writer::create(file.path(), one_group(), WriterOptions{.fragment_bytes = 1000});
    ASSERT_TRUE(writer);
    for (int sample = 0; sample < 10'000; ++sample)
      ASSERT_TRUE(writer.value().append(0, sample, std::vector<Value>{static_cast<std::int16_t>(sample)}));
  }
  const WrittenFile bytes{file.bytes()};
  const auto group = bytes.at<std::uint64_t>(64 + 24);
  std::uint64_t records = 0;
  std::uint64_t lists = 0;
  for (auto list = bytes.at<std::uint64_t>(group + 40); list != 0; list = bytes.at<std::uint64_t>(list + 24)) {
    bytes.expect_block(list, "##DL", 56, 2);
    EXPECT_EQ(bytes.at<std::uint64_t>(list + 48), records * 11);
    const auto data = bytes.at<std::uint64_t>(list + 32);
    const auto length = bytes.at<std::uint64_t>(data + 8);
    bytes.expect_block(data, "##DT", length, 0);
    EXPECT_LE(length - 24, 1000u + 11u);
    EXPECT_EQ(bytes.at<double>(data + 24), static_cast<double>(records));  // the first record's time
    records += (length - 24) / 11;
    ASSERT_LT(++lists, 1000u);
  }
  EXPECT_EQ(records, 10'000u);
  EXPECT_EQ(lists, 10'000u / 91 + 1);  // 91 records of 11 bytes fill a fragment of 1000
}

}  // namespace
}  // namespace duet::mdf4
