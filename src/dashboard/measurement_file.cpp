#include "measurement_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "duet/mdf4/exact_value.hpp"
#include "duet/mdf4/writer.hpp"

namespace duet::dashboard {
namespace {

// Whether `value` is exactly a `type`; a missing sample (NaN) is one of every type.
bool fits(mdf4::ValueType type, double value) { return std::isnan(value) || mdf4::exactly(type, value).has_value(); }

// Precondition: fits(type, value).
mdf4::Value stored_value(mdf4::ValueType type, double value) {
  if (std::isnan(value)) return std::monostate{};
  return *mdf4::exactly(type, value);
}

struct StoredType {
  std::string_view name;  // as the description names it
  mdf4::ValueType type;
};

constexpr StoredType f64_type{"float64", mdf4::ValueType::f64};
constexpr StoredType stored_types[] = {
    {"uint8", mdf4::ValueType::u8},    {"int8", mdf4::ValueType::i8},
    {"uint16", mdf4::ValueType::u16},  {"int16", mdf4::ValueType::i16},
    {"uint32", mdf4::ValueType::u32},  {"int32", mdf4::ValueType::i32},
    {"uint64", mdf4::ValueType::u64},  {"int64", mdf4::ValueType::i64},
    {"float32", mdf4::ValueType::f32}, f64_type,
};

// The described type when every value fits it, else f64 with a comment saying why.
const StoredType& stored_type(const MeasuredSignal& signal, std::string& comment) {
  for (const StoredType& stored : stored_types) {
    if (stored.name != signal.described_type) continue;
    for (const double value : signal.values) {
      if (!fits(stored.type, value)) {
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
      row[signal] = stored_value(stored[signal]->type, measurement.signals[signal].values[sample]);
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
