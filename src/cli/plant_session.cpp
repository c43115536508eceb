#include "plant_session.hpp"

#include <memory>

namespace duet::cli {

PlantSession::PlantSession(link::NamedPipes pipes, plant::Plant& plant, const link::ServeOptions& options,
                           link::Timeout connect_within)
    : pipes_(std::move(pipes)),
      thread_([this, &plant, options, connect_within] { run(plant, options, connect_within); }) {}

PlantSession::~PlantSession() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

PlantSession::Outcome PlantSession::join() {
  thread_.join();
  return outcome_;
}

void PlantSession::run(plant::Plant& plant, const link::ServeOptions& options, link::Timeout connect_within) {
  // Waits in slices, so that cancel() is seen: an emulator that ended before connecting must not keep us here.
  constexpr link::Timeout slice{100};
  const auto deadline = std::chrono::steady_clock::now() + connect_within;
  std::unique_ptr<link::FdStream> accepted;
  while (!accepted && !cancelled_.load() && std::chrono::steady_clock::now() < deadline) {
    auto attempt = pipes_.accept(slice);  // a failure is the slice's end (or a passing error): try again
    if (attempt) accepted = std::move(attempt).value();
  }
  if (!accepted) {
    outcome_.served =
        Failure{"no firmware opened the plant's pipes within " + std::to_string(connect_within.count() / 1000) + " s"};
    finished_.store(true);
    return;
  }
  outcome_.connected = true;
  connected_.store(true);
  const auto start = std::chrono::steady_clock::now();
  outcome_.served = link::serve(plant, *accepted, options, outcome_.summary);
  outcome_.wall_time = std::chrono::steady_clock::now() - start;
  finished_.store(true);
}

}  // namespace duet::cli
