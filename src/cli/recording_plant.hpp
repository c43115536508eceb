#pragma once
// The plant's own view of a session: a plant that records what the plant behind it shows of itself
// (Plant::observables) once per TICK, after it advanced, whatever the firmware measures; and the files that
// recording is written to (--csv, --plot, --mdf of `duet plant serve` and `duet pil`).

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::cli {

class RecordingPlant : public plant::Plant {
 public:
  // Each row as it is recorded (`duet pil` streams them into its MDF file), in the session's thread.
  using RowSink = std::function<void(double time_s, std::span<const double> row)>;

  // Without `record` it only passes the calls on. `sink`, if any, takes every row, also those past what is kept.
  RecordingPlant(std::unique_ptr<plant::Plant> behind, bool record, RowSink sink = {});

  [[nodiscard]] Status start(double base_period_s) override { return behind_->start(base_period_s); }
  void advance(double time_s, const plant::RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override { behind_->write(resource, values); }
  void read(std::string_view resource, std::span<double> values) override { behind_->read(resource, values); }
  [[nodiscard]] std::vector<Observable> observables() const override { return observables_; }
  void observe(std::span<double> values) const override { behind_->observe(values); }
  [[nodiscard]] std::optional<Halt> halted() const override { return behind_->halted(); }

  // A row per TICK: `time_s` and a column per observable. Read it once the session is over (not thread-safe).
  [[nodiscard]] const model::Recording& recording() const { return recording_; }
  // Whether the session went on past what is kept in memory (the recording then holds its beginning).
  [[nodiscard]] bool truncated() const { return truncated_; }

 private:
  std::unique_ptr<plant::Plant> behind_;
  bool record_;
  RowSink sink_;
  std::vector<Observable> observables_;
  std::vector<double> now_;
  model::Recording recording_;
  // A session in real time may run for hours: keep at most 100 million values (800 MB), as duet sim does.
  std::size_t most_rows_;
  bool truncated_ = false;
};

// Where a recording goes; an empty path is not written.
struct RecordingFiles {
  std::string csv;   // like duet sim's: time_s and a column per quantity, numbers that read back as the same doubles
  std::string plot;  // an SVG plot with a panel per unit
  std::string mdf;   // an MDF 4 file of one group, the quantities as doubles (docs/MDF4.md)
  [[nodiscard]] bool any() const { return !csv.empty() || !plot.empty() || !mdf.empty(); }
};

// Creates the files, empty, so that a path that cannot be written fails before a session rather than after it.
[[nodiscard]] Status create_recording_files(const RecordingFiles& files);
// Writes `recording` to the files; `title` heads the plot.
[[nodiscard]] Status write_recording_files(const model::Recording& recording, const RecordingFiles& files,
                                           const std::string& title);
// Writes `text` to `path`; the failure names the path.
[[nodiscard]] Status write_text_file(const std::string& path, const std::string& text);

}  // namespace duet::cli
