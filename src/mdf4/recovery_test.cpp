// A recording killed mid-way: the child process writes and dies by SIGKILL; the reader recovers every sample that
// reached the file in a whole fragment.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/writer.hpp"
#include "test_files.hpp"

namespace duet::mdf4 {
namespace {

using testing::TemporaryFile;

FileSpec two_groups() {
  return FileSpec{.groups = {{.name = "fast", .comment = "", .channels = {{.name = "n", .type = ValueType::u32}}},
                             {.name = "slow", .comment = "", .channels = {{.name = "x", .type = ValueType::f64}}}}};
}

// What a crash does: the process ends at once, without the writer's destructor.
[[noreturn]] void die() {
  ::kill(::getpid(), SIGKILL);
  ::_exit(0);  // not reached
}

// Runs `write` in a child, which must die() with its writer alive; returns once the child is dead.
template <typename Write>
void write_and_die(const Write& write) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    write();
    ::_exit(1);  // `write` did not die
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

TEST(Mdf4Recovery, AKilledWriterLeavesAFileWhoseWholeFragmentsAreRead) {
  const TemporaryFile file{"killed.mf4"};
  // fast: 8 + 4 + 1 = 13 bytes a record, 20 to a 256-byte fragment; slow: 8 + 8 + 1 = 17, 16 to a fragment.
  write_and_die([&] {
    auto writer = Writer::create(file.path(), two_groups(), WriterOptions{.fragment_bytes = 256});
    if (!writer) ::_exit(1);
    for (std::uint32_t sample = 0; sample < 1010; ++sample) {
      (void)writer.value().append(0, sample * 0.001, std::vector<Value>{sample});
      if (sample % 10 == 0) (void)writer.value().append(1, sample * 0.001, std::vector<Value>{sample * 0.5});
    }
    die();
  });
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  const FileInfo& info = reader.value().info();
  EXPECT_FALSE(info.finalised);
  EXPECT_EQ(info.unfinalised_flags, 0x01);
  EXPECT_EQ(info.groups[0].samples, 1000u);  // 50 fragments; the 10 records still buffered are lost
  EXPECT_EQ(info.groups[1].samples, 96u);    // 6 fragments of 16 of the 101
  std::uint32_t expected = 0;
  ASSERT_TRUE(reader.value().for_each_record(0, [&](const Record& record) {
    EXPECT_EQ(std::get<std::uint64_t>(record.value(1)), expected);
    EXPECT_EQ(record.time(), expected * 0.001);
    ++expected;
  }));
  EXPECT_EQ(expected, 1000u);
}

TEST(Mdf4Recovery, WhatWasFlushedSurvives) {
  const TemporaryFile file{"flushed.mf4"};
  write_and_die([&] {
    auto writer = Writer::create(file.path(), two_groups());
    if (!writer) ::_exit(1);
    for (std::uint32_t sample = 0; sample < 7; ++sample)
      (void)writer.value().append(0, sample, std::vector<Value>{sample});
    (void)writer.value().flush();
    (void)writer.value().append(0, 8, std::vector<Value>{std::uint32_t{8}});  // buffered: lost
    die();
  });
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  EXPECT_EQ(reader.value().info().groups[0].samples, 7u);
  EXPECT_EQ(reader.value().info().groups[1].samples, 0u);
}

TEST(Mdf4Recovery, AFileKilledBeforeAnyDataHasItsGroupsAndNoSamples) {
  const TemporaryFile file{"early.mf4"};
  write_and_die([&] {
    auto writer = Writer::create(file.path(), two_groups());
    die();
  });
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  EXPECT_FALSE(reader.value().info().finalised);
  ASSERT_EQ(reader.value().info().groups.size(), 2u);
  EXPECT_EQ(reader.value().info().groups[1].channels[1].name, "x");
}

}  // namespace
}  // namespace duet::mdf4
