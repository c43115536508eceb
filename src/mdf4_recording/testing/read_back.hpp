#pragma once
// For the tests of MDF recordings: a file path removed at the end of the test, and a group's samples read back.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "duet/mdf4/reader.hpp"

namespace duet::mdf4_recording::testing {

class TemporaryPath {
 public:
  explicit TemporaryPath(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("duet_mdf4_recording_" + std::to_string(::getpid()) + "_" + name)) {}
  ~TemporaryPath() { std::filesystem::remove(path_); }
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// One record: its time and, per channel after the master, the physical value (NaN when the sample is invalid).
struct Sample {
  double time_s = 0;
  std::vector<mdf4::Number> stored;
  std::vector<bool> valid;
  std::vector<double> physical;
};

inline std::vector<Sample> samples_of(const mdf4::Reader& reader, std::size_t group) {
  std::vector<Sample> samples;
  const Status read = reader.for_each_record(group, [&](const mdf4::Record& record) {
    Sample sample{record.time(), {}, {}, {}};
    const auto& channels = reader.info().groups[group].channels;
    for (std::size_t channel = 0; channel < channels.size(); ++channel) {
      if (reader.info().groups[group].master == channel) continue;
      sample.stored.push_back(record.value(channel));
      sample.valid.push_back(record.valid(channel));
      const mdf4::Physical physical = record.physical(channel);
      sample.physical.push_back(std::holds_alternative<double>(physical) ? std::get<double>(physical)
                                : std::holds_alternative<mdf4::Number>(physical)
                                    ? mdf4::to_double(std::get<mdf4::Number>(physical))
                                    : NAN);
    }
    samples.push_back(std::move(sample));
  });
  EXPECT_TRUE(read.ok()) << (read.ok() ? "" : read.error());
  return samples;
}

}  // namespace duet::mdf4_recording::testing
