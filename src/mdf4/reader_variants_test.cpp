// Files as other writers lay them out (docs/MDF4.md, "Reading"), built by hand: the reader gets the same samples.
#include <gtest/gtest.h>

#include "duet/mdf4/reader.hpp"
#include "hand_made_file.hpp"

namespace duet::mdf4 {
namespace {

using testing::HandMadeFile;
using testing::RecordBytes;

Reader open(const HandMadeFile& file) {
  auto reader = Reader::from_bytes(file.bytes, "hand-made.mf4");
  EXPECT_TRUE(reader) << reader.error();
  if (!reader) std::abort();
  return std::move(reader.value());
}

std::vector<double> column(const Reader& reader, std::size_t group, std::size_t channel) {
  std::vector<double> values;
  EXPECT_TRUE(reader.for_each_record(group, [&](const Record& record) {
    const Physical physical = record.physical(channel);
    values.push_back(std::holds_alternative<double>(physical) ? std::get<double>(physical)
                                                              : to_double(std::get<Number>(physical)));
  }));
  return values;
}

// MDF 4.10, texts of exact length (mdflib), MD comments, a channel group of 4.2 with its seventh link.
TEST(Mdf4ReaderVariants, Version410WithMdCommentsAndExactTextLengths) {
  HandMadeFile file{"MDF     ", "4.10    ", 410};
  const std::size_t header = file.header();
  const std::size_t group = file.data_group();
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(0, 2, 12, 0, 7);
  file.link(group, 1, channel_group);
  file.link(channel_group, 2, file.tx("event 1", "##TX", false));
  const std::size_t time = file.channel("t", 2, 4, 0, 64);
  file.link(channel_group, 1, time);
  const std::size_t value = file.channel("v", 0, 4, 8, 32);
  file.link(time, 0, value);
  file.link(value, 6, file.tx("V", "##TX", false));
  file.link(
      value, 7,
      file.tx("<CNcomment xmlns=\"http://www.asam.net/mdf/v4\"><TX>volts &amp; more</TX></CNcomment>", "##MD", false));
  file.link(group, 2, file.data_block(RecordBytes{}.add(0.0).add(1.5f).add(0.1).add(-2.5f).bytes));
  const Reader reader = open(file);
  EXPECT_EQ(reader.info().version, "4.10");
  EXPECT_EQ(reader.info().program, "other");
  const GroupInfo& info = reader.info().groups[0];
  EXPECT_EQ(info.name, "event 1");
  EXPECT_EQ(info.channels[1].unit, "V");
  EXPECT_EQ(info.channels[1].comment, "volts & more");
  EXPECT_EQ(column(reader, 0, 1), (std::vector<double>{1.5, -2.5}));
  EXPECT_EQ(column(reader, 0, 0), (std::vector<double>{0.0, 0.1}));
}

// Several channel groups in one data group, each record prefixed by its group's 1-byte id (mdflib writes so).
TEST(Mdf4ReaderVariants, UnsortedRecordsWithIds) {
  HandMadeFile file;
  const std::size_t header = file.header();
  const std::size_t group = file.data_group(1);
  file.link(header, 0, group);
  const std::size_t first = file.channel_group(1, 2, 10, 0);
  const std::size_t second = file.channel_group(2, 1, 9, 0);
  file.link(group, 1, first);
  file.link(first, 0, second);
  const std::size_t first_time = file.channel("time", 2, 4, 0, 64);
  file.link(first_time, 0, file.channel("a", 0, 2, 8, 16));
  file.link(first, 1, first_time);
  const std::size_t second_time = file.channel("time", 2, 4, 0, 64);
  file.link(second_time, 0, file.channel("b", 0, 0, 8, 8));
  file.link(second, 1, second_time);
  RecordBytes records;
  records.add(std::uint8_t{1}).add(0.0).add(std::int16_t{-7});
  records.add(std::uint8_t{2}).add(0.05).add(std::uint8_t{200});
  records.add(std::uint8_t{1}).add(0.1).add(std::int16_t{9});
  file.link(group, 2, file.data_block(records.bytes));
  const Reader reader = open(file);
  ASSERT_EQ(reader.info().groups.size(), 2u);
  EXPECT_EQ(reader.info().groups[0].samples, 2u);
  EXPECT_EQ(column(reader, 0, 1), (std::vector<double>{-7, 9}));
  EXPECT_EQ(column(reader, 0, 0), (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(column(reader, 1, 1), (std::vector<double>{200}));
}

// The common streaming layout: one DT growing at the end, its length and the count not yet updated (flags 0x05),
// the last record torn by the crash.
TEST(Mdf4ReaderVariants, AnUnfinalisedGrowingDataBlockIsRecovered) {
  HandMadeFile file{"UnFinMF ", "4.20    ", 420, 0x05};
  const std::size_t header = file.header();
  const std::size_t group = file.data_group();
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(0, 0, 10, 0);
  file.link(group, 1, channel_group);
  const std::size_t time = file.channel("time", 2, 4, 0, 64);
  file.link(time, 0, file.channel("n", 0, 0, 8, 16));
  file.link(channel_group, 1, time);
  const std::size_t data = file.data_block({});
  file.link(group, 2, data);
  const auto records = RecordBytes{}.add(0.0).add(std::uint16_t{1}).add(1.0).add(std::uint16_t{2}).add(2.0).bytes;
  file.append_raw(records.data(), records.size());  // the third record lacks its value
  const Reader reader = open(file);
  EXPECT_FALSE(reader.info().finalised);
  EXPECT_EQ(reader.info().groups[0].samples, 2u);
  EXPECT_EQ(column(reader, 0, 1), (std::vector<double>{1, 2}));
}

// A list of two data blocks with one equal length, a record split across them, under a header list.
TEST(Mdf4ReaderVariants, ADataListUnderAHeaderListWithARecordAcrossBlocks) {
  HandMadeFile file;
  const std::size_t header = file.header();
  const std::size_t group = file.data_group();
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(0, 3, 4, 0);
  file.link(group, 1, channel_group);
  file.link(channel_group, 1, file.channel("n", 0, 0, 0, 32));
  const auto records = RecordBytes{}.add(std::uint32_t{10}).add(std::uint32_t{20}).add(std::uint32_t{30}).bytes;
  const std::size_t part1 = file.data_block({records.begin(), records.begin() + 6});
  const std::size_t part2 = file.data_block({records.begin() + 6, records.end()});
  const std::size_t list = file.block("##DL", 3, 16);
  file.link(list, 1, part1);
  file.link(list, 2, part2);
  file.put<std::uint8_t>(list + 48, 1);  // equal length
  file.put<std::uint32_t>(list + 52, 2);
  file.put<std::uint64_t>(list + 56, 6);
  const std::size_t header_list = file.block("##HL", 1, 16);
  file.link(header_list, 0, list);
  file.link(group, 2, header_list);
  const Reader reader = open(file);
  EXPECT_EQ(column(reader, 0, 0), (std::vector<double>{10, 20, 30}));
}

// Big-endian values, bit fields, a virtual time master scaled by a linear conversion, value-to-text.
TEST(Mdf4ReaderVariants, BigEndianBitFieldsVirtualMasterAndTexts) {
  HandMadeFile file;
  const std::size_t header = file.header();
  const std::size_t group = file.data_group();
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(0, 2, 8, 0);
  file.link(group, 1, channel_group);
  const std::size_t time = file.channel("time", 3, 0, 0, 0);
  const std::size_t scale = file.block("##CC", 4, 40);
  file.put<std::uint8_t>(scale + 56, 1);
  file.put<std::uint16_t>(scale + 62, 2);
  file.put<double>(scale + 80, 10.0);
  file.put<double>(scale + 88, 0.01);
  file.link(time, 4, scale);
  const std::size_t big = file.channel("big", 0, 3, 0, 16);        // i16 big-endian at 0
  const std::size_t field = file.channel("field", 0, 2, 2, 5, 3);  // i5 at byte 2, bit 3
  const std::size_t state = file.channel("state", 0, 0, 3, 8);
  const std::size_t real = file.channel("real", 0, 5, 4, 32);    // f32 big-endian at 4
  const std::size_t texts = file.block("##CC", 4 + 3, 24 + 16);  // two keys, a default
  file.put<std::uint8_t>(texts + 80, 7);
  file.put<std::uint16_t>(texts + 84, 3);
  file.put<std::uint16_t>(texts + 86, 2);
  file.put<double>(texts + 104, 0.0);
  file.put<double>(texts + 112, 1.0);
  file.link(texts, 4, file.tx("off"));
  file.link(texts, 5, file.tx("on"));
  file.link(texts, 6, file.tx("unknown"));
  file.link(state, 4, texts);
  file.link(channel_group, 1, time);
  file.link(time, 0, big);
  file.link(big, 0, field);
  file.link(field, 0, state);
  file.link(state, 0, real);
  // record 0: big = 0x0102 (258), field bits 3..7 of 0b10101000 = 0b10101 (-11), state 1, real 2.5f big-endian.
  // record 1: big = 0xFFFE (-2), field 0b01000 << 3 (8), state 5, real -1.0f.
  file.link(group, 2, file.data_block({0x01, 0x02, 0xA8, 1, 0x40, 0x20, 0, 0, 0xFF, 0xFE, 0x40, 5, 0xBF, 0x80, 0, 0}));
  const Reader reader = open(file);
  const GroupInfo& info = reader.info().groups[0];
  EXPECT_EQ(info.master, 0u);
  EXPECT_EQ(column(reader, 0, 0), (std::vector<double>{10.0, 10.01}));
  EXPECT_EQ(column(reader, 0, 1), (std::vector<double>{258, -2}));
  EXPECT_EQ(column(reader, 0, 2), (std::vector<double>{-11, 8}));
  EXPECT_EQ(column(reader, 0, 4), (std::vector<double>{2.5, -1.0}));
  std::vector<std::string> states;
  ASSERT_TRUE(reader.for_each_record(
      0, [&](const Record& record) { states.push_back(std::get<std::string>(record.physical(3))); }));
  EXPECT_EQ(states, (std::vector<std::string>{"on", "unknown"}));
}

// An unfinalised list whose last links the writer had not filled yet (flag 0x10): the filled ones are read.
TEST(Mdf4ReaderVariants, AnUnfinishedDataListEndsAtItsFirstNilLink) {
  HandMadeFile file{"UnFinMF ", "4.20    ", 420, 0x11};
  const std::size_t header = file.header();
  const std::size_t group = file.data_group();
  file.link(header, 0, group);
  const std::size_t channel_group = file.channel_group(0, 0, 1, 0);
  file.link(group, 1, channel_group);
  file.link(channel_group, 1, file.channel("n", 0, 0, 0, 8));
  const std::size_t list = file.block("##DL", 4, 8 + 24);
  file.put<std::uint32_t>(list + 24 + 32 + 4, 3);
  file.link(list, 1, file.data_block({1, 2}));
  file.link(group, 2, list);
  const Reader reader = open(file);
  EXPECT_EQ(column(reader, 0, 0), (std::vector<double>{1, 2}));
}

}  // namespace
}  // namespace duet::mdf4
