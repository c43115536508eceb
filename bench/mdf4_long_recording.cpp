// A long MDF 4 recording with flat memory: writes SAMPLES samples of 16 f64 signals (default: one hour at 1 kHz),
// printing the peak resident memory as it goes, then reads every value back and checks it. Exits 1 on any mismatch.
//   build/host-release/bench/mdf4_long_recording [SAMPLES] [FILE]
// docs/PERFORMANCE.md, "Recording"; measure the whole with /usr/bin/time -v.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/writer.hpp"

namespace {

constexpr std::size_t signals = 16;

long peak_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

double value_of(std::uint64_t sample, std::size_t signal) {
  return static_cast<double>(sample) * 0.5 + static_cast<double>(signal);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run(int argc, char** argv) {
  const std::uint64_t samples = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 3'600'000;
  const std::filesystem::path file =
      argc > 2 ? std::filesystem::path{argv[2]}
               : std::filesystem::temp_directory_path() / ("duet_long_" + std::to_string(::getpid()) + ".mf4");
  duet::mdf4::GroupSpec group{.name = "rate 1", .comment = "", .channels = {}};
  group.channels.push_back({.name = "signal", .type = duet::mdf4::ValueType::f64, .elements = signals});
  const auto start = std::chrono::steady_clock::now();
  {
    auto writer = duet::mdf4::Writer::create(file, duet::mdf4::FileSpec{.groups = {group}});
    if (!writer) {
      std::fprintf(stderr, "%s\n", writer.error().c_str());
      return 1;
    }
    std::vector<duet::mdf4::Value> values(signals);
    for (std::uint64_t sample = 0; sample < samples; ++sample) {
      for (std::size_t signal = 0; signal < signals; ++signal) values[signal] = value_of(sample, signal);
      if (duet::Status appended = writer.value().append(0, static_cast<double>(sample) * 0.001, values); !appended) {
        std::fprintf(stderr, "%s\n", appended.error().c_str());
        return 1;
      }
      if ((sample + 1) % (samples / 10 == 0 ? 1 : samples / 10) == 0)
        std::printf("written %llu samples, peak RSS %ld kB\n", static_cast<unsigned long long>(sample) + 1,
                    peak_rss_kb());
    }
    if (duet::Status finalised = writer.value().finalise(); !finalised) {
      std::fprintf(stderr, "%s\n", finalised.error().c_str());
      return 1;
    }
  }
  const double write_s = seconds_since(start);
  const double megabytes = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
  std::printf("wrote %.1f MB in %.2f s: %.0f MB/s, %.2f million samples/s\n", megabytes, write_s, megabytes / write_s,
              static_cast<double>(samples) / write_s / 1e6);

  const auto read_start = std::chrono::steady_clock::now();
  auto reader = duet::mdf4::Reader::open(file);
  if (!reader) {
    std::fprintf(stderr, "%s\n", reader.error().c_str());
    return 1;
  }
  std::uint64_t read = 0;
  std::uint64_t wrong = 0;
  const duet::Status walked = reader.value().for_each_record(0, [&](const duet::mdf4::Record& record) {
    for (std::size_t signal = 0; signal < signals; ++signal) {
      if (std::get<double>(record.value(signal + 1)) != value_of(record.index(), signal)) ++wrong;
    }
    ++read;
  });
  std::filesystem::remove(file);
  std::printf("read back %llu samples in %.2f s, %llu values wrong; peak RSS %ld kB\n",
              static_cast<unsigned long long>(read), seconds_since(read_start), static_cast<unsigned long long>(wrong),
              peak_rss_kb());
  return walked && read == samples && wrong == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& failure) {  // the file system's errors
    std::fprintf(stderr, "%s\n", failure.what());
    return 1;
  }
}
