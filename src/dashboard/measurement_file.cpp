#include "measurement_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <type_traits>

#include "duet/mdf4/writer.hpp"

namespace duet::dashboard {
namespace {

// Whether `value` is exactly a T; a missing sample (NaN) is one of every type.
template <typename T>
bool fits(double value) {
  if (std::isnan(value) || std::is_same_v<T, double>) return true;
  if constexpr (std::is_same_v<T, float>) {
    if (std::isinf(value)) return true;
    return std::fabs(value) <= std::numeric_limits<float>::max() &&
           static_cast<double>(static_cast<float>(value)) == value;
  } else {
    // max() + 1 is exact below 64 bits, and rounds to 2^63 or 2^64 at 64 bits: the first value past the type.
    return value == std::trunc(value) && value >= static_cast<double>(std::numeric_limits<T>::min()) &&
           value < static_cast<double>(std::numeric_limits<T>::max()) + 1.0;
  }
}

// Precondition: fits<T>(value).
template <typename T>
mdf4::Value value_as(double value) {
  if (std::isnan(value)) return std::monostate{};
  return static_cast<T>(value);
}

struct StoredType {
  std::string_view name;  // as the description names it
  mdf4::ValueType type;
  bool (*fits)(double);
  mdf4::Value (*value)(double);
};

constexpr StoredType f64_type{"float64", mdf4::ValueType::f64, fits<double>, value_as<double>};
constexpr StoredType stored_types[] = {
    {"uint8", mdf4::ValueType::u8, fits<std::uint8_t>, value_as<std::uint8_t>},
    {"int8", mdf4::ValueType::i8, fits<std::int8_t>, value_as<std::int8_t>},
    {"uint16", mdf4::ValueType::u16, fits<std::uint16_t>, value_as<std::uint16_t>},
    {"int16", mdf4::ValueType::i16, fits<std::int16_t>, value_as<std::int16_t>},
    {"uint32", mdf4::ValueType::u32, fits<std::uint32_t>, value_as<std::uint32_t>},
    {"int32", mdf4::ValueType::i32, fits<std::int32_t>, value_as<std::int32_t>},
    {"uint64", mdf4::ValueType::u64, fits<std::uint64_t>, value_as<std::uint64_t>},
    {"int64", mdf4::ValueType::i64, fits<std::int64_t>, value_as<std::int64_t>},
    {"float32", mdf4::ValueType::f32, fits<float>, value_as<float>},
    f64_type,
};

// The described type when every value fits it, else f64 with a comment saying why.
const StoredType& stored_type(const MeasuredSignal& signal, std::string& comment) {
  for (const StoredType& stored : stored_types) {
    if (stored.name != signal.described_type) continue;
    for (const double value : signal.values) {
      if (!stored.fits(value)) {
        comment = "described as " + signal.described_type + "; stored as float64: a value is no " +
                  signal.described_type + " (a conversion of the target's, or a bad sample)";
        return f64_type;
      }
    }
    return stored;
  }
  comment = signal.described_type.empty() ? "type not known to the back end; stored as float64"
                                          : "type '" + signal.described_type + "' not known; stored as float64";
  return f64_type;
}

// A file of its own in the temporary folder, removed with this object: the writer writes to a path.
class TemporaryFile {
 public:
  TemporaryFile() {
    std::string name = (std::filesystem::temp_directory_path() / "duet-dashboard-XXXXXX.mf4").string();
    const int file = ::mkstemps(name.data(), 4);
    if (file < 0) {
      problem_ = "cannot make a temporary file in " + std::filesystem::temp_directory_path().string() + ": " +
                 std::strerror(errno);
      return;
    }
    ::close(file);
    path_ = name;
  }
  ~TemporaryFile() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove(path_, ignored);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] const std::string& problem() const { return problem_; }

 private:
  std::filesystem::path path_;
  std::string problem_;
};

}  // namespace

Result<std::string> mdf4_bytes(const Measurement& measurement) {
  mdf4::FileSpec spec{.groups = {}, .start_time_ns = measurement.start_time_ns, .comment = measurement.file_comment};
  mdf4::GroupSpec group{.name = measurement.group_name, .comment = measurement.group_comment, .channels = {}};
  std::vector<const StoredType*> stored;
  for (const MeasuredSignal& signal : measurement.signals) {
    if (signal.values.size() != measurement.time_s.size())
      return Failure{"signal '" + signal.name + "' has " + std::to_string(signal.values.size()) + " values for " +
                     std::to_string(measurement.time_s.size()) + " times"};
    std::string comment;
    stored.push_back(&stored_type(signal, comment));
    group.channels.push_back({.name = signal.name,
                              .type = stored.back()->type,
                              .unit = signal.unit,
                              .comment = comment,
                              .conversion = std::nullopt,
                              .elements = 1});
  }
  spec.groups.push_back(std::move(group));

  const TemporaryFile file;
  if (file.path().empty()) return Failure{file.problem()};
  auto writer = mdf4::Writer::create(file.path(), spec);
  if (!writer) return Failure{writer.error()};
  std::vector<mdf4::Value> row(measurement.signals.size());
  for (std::size_t sample = 0; sample < measurement.time_s.size(); ++sample) {
    for (std::size_t signal = 0; signal < row.size(); ++signal)
      row[signal] = stored[signal]->value(measurement.signals[signal].values[sample]);
    if (Status appended = writer.value().append(0, measurement.time_s[sample], row); !appended)
      return Failure{appended.error()};
  }
  if (Status finalised = writer.value().finalise(); !finalised) return Failure{finalised.error()};
  std::ifstream written{file.path(), std::ios::binary};
  std::string bytes{std::istreambuf_iterator<char>{written}, std::istreambuf_iterator<char>{}};
  if (!written && !written.eof()) return Failure{file.path().string() + ": cannot be read back"};
  return bytes;
}

std::int64_t start_time_ns(double newest_time_s, std::int64_t now_ns) {
  const double newest_ns = newest_time_s * 1e9;
  if (!(newest_ns >= 0 && newest_ns <= static_cast<double>(now_ns))) return now_ns;
  return now_ns - static_cast<std::int64_t>(newest_ns);
}

}  // namespace duet::dashboard
