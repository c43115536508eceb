#include "duet/mdf4_recording/plant_and_daq_file.hpp"

namespace duet::mdf4_recording {
namespace {

constexpr auto flush_period = std::chrono::seconds{1};

}  // namespace

PlantAndDaqFile::PlantAndDaqFile(DaqFile file)
    : file_(std::move(file)), next_flush_(std::chrono::steady_clock::now() + flush_period) {}

Result<std::unique_ptr<PlantAndDaqFile>> PlantAndDaqFile::create(const std::filesystem::path& path,
                                                                 const PlantColumns& plant, std::vector<DaqGroup> lists,
                                                                 const std::string& comment,
                                                                 std::int64_t start_time_ns) {
  mdf4::GroupSpec tick{.name = "every tick", .comment = "the plant's own quantities", .channels = {}};
  for (std::size_t column = 0; column < plant.names.size(); ++column) {
    tick.channels.push_back({.name = plant.names[column],
                             .type = mdf4::ValueType::f64,
                             .unit = column < plant.units.size() ? plant.units[column] : std::string{},
                             .comment = {},
                             .conversion = std::nullopt,
                             .elements = 1});
  }
  auto file = DaqFile::create(path, std::move(lists), comment, start_time_ns, {std::move(tick)});
  if (!file) return Failure{file.error()};
  return std::unique_ptr<PlantAndDaqFile>{new PlantAndDaqFile{std::move(file).value()}};
}

void PlantAndDaqFile::append_plant(double time_s, std::span<const double> values) {
  const std::scoped_lock lock{mutex_};
  if (failure_ || finalised_) return;
  row_.assign(values.begin(), values.end());
  took(file_.append_before(0, time_s, row_));
}

void PlantAndDaqFile::append_daq(std::size_t list, double time_s, std::optional<std::span<const std::uint8_t>> bytes) {
  const std::scoped_lock lock{mutex_};
  if (failure_ || finalised_) return;
  took(file_.append(list, time_s, bytes));
}

void PlantAndDaqFile::took(Status appended) {
  if (!appended) {
    failure_ = Failure{appended.error()};
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now < next_flush_) return;
  next_flush_ = now + flush_period;
  if (Status flushed = file_.flush(); !flushed) failure_ = Failure{flushed.error()};
}

Status PlantAndDaqFile::finalise() {
  const std::scoped_lock lock{mutex_};
  if (!finalised_) {
    finalised_ = true;
    // After a failed append the file is finalised all the same: what came before the failure is kept whole.
    if (Status finalised = file_.finalise(); !finalised && !failure_) failure_ = Failure{finalised.error()};
  }
  if (failure_) return *failure_;
  return done();
}

}  // namespace duet::mdf4_recording
