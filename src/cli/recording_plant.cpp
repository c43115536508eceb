#include "recording_plant.hpp"

#include <chrono>
#include <fstream>

#include "duet/mdf4_recording/recording_file.hpp"
#include "duet/plot/figure.hpp"

namespace duet::cli {

RecordingPlant::RecordingPlant(std::unique_ptr<plant::Plant> behind, bool record, RowSink sink)
    : behind_(std::move(behind)),
      record_(record),
      sink_(std::move(sink)),
      observables_(behind_->observables()),
      now_(observables_.size()),
      most_rows_(100'000'000 / (observables_.size() + 1)) {
  for (const Observable& observable : observables_) {
    recording_.names.push_back(observable.name);
    recording_.units.push_back(observable.unit);
  }
  recording_.columns.resize(observables_.size());
}

void RecordingPlant::advance(double time_s, const plant::RaiseInterrupt& raise) {
  behind_->advance(time_s, raise);
  if (!record_) return;
  behind_->observe(now_);
  if (sink_) sink_(time_s, now_);
  if (recording_.time_s.size() >= most_rows_) {
    truncated_ = true;
    return;
  }
  recording_.time_s.push_back(time_s);
  for (std::size_t k = 0; k < now_.size(); ++k) recording_.columns[k].push_back(now_[k]);
}

Status write_text_file(const std::string& path, const std::string& text) {
  std::ofstream file{path};
  file << text;
  file.close();
  if (!file) return Failure{"cannot write " + path};
  return done();
}

Status create_recording_files(const RecordingFiles& files) {
  for (const std::string& path : {files.csv, files.plot, files.mdf}) {
    if (path.empty()) continue;
    if (Status created = write_text_file(path, ""); !created) return created;
  }
  return done();
}

Status write_recording_files(const model::Recording& recording, const RecordingFiles& files, const std::string& title) {
  std::string problems;  // every file is tried whatever happens to the others
  const auto attempt = [&problems](const std::string& path, const std::string& text) {
    if (Status written = write_text_file(path, text); !written)
      problems += (problems.empty() ? "" : "; ") + written.error();
  };
  if (!files.csv.empty()) attempt(files.csv, model::to_csv(recording));
  if (!files.plot.empty()) {
    plot::Figure figure{title, "s", recording.time_s, {}};
    for (std::size_t k = 0; k < recording.names.size(); ++k)
      figure.series.push_back({recording.names[k], recording.units[k], recording.columns[k]});
    attempt(files.plot, plot::to_svg(figure));
  }
  if (!files.mdf.empty()) {
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    const Status written = mdf4_recording::write_recording_file(
        files.mdf, recording,
        {.group = "every tick",
         .comment = title,
         .start_time_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now).count(),
         .program = nullptr});
    if (!written) problems += (problems.empty() ? "" : "; ") + written.error();
  }
  if (!problems.empty()) return Failure{problems};
  return done();
}

}  // namespace duet::cli
