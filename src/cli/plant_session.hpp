#pragma once
// One firmware's session with a plant, served in a thread of its own while the caller watches other things (the
// emulator, signals): waits for the firmware to open the named pipes, then serve()s it until it says BYE or its
// stream ends.

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

#include "duet/link/named_pipes.hpp"
#include "duet/link/serve.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::cli {

class PlantSession {
 public:
  struct Outcome {
    Status served = Failure{"no session"};
    link::ServeSummary summary;                 // what the session got to, even one that failed or was cut
    bool connected = false;                     // whether the firmware connected at all
    std::chrono::duration<double> wall_time{};  // from the connection to the session's end
  };

  // Starts the thread. `plant` must outlive the session; read what it recorded after join(). The firmware has
  // `connect_within` to connect.
  PlantSession(link::NamedPipes pipes, plant::Plant& plant, const link::ServeOptions& options,
               link::Timeout connect_within);
  PlantSession(const PlantSession&) = delete;
  PlantSession& operator=(const PlantSession&) = delete;
  // Cancels and joins.
  ~PlantSession();

  // Whether the thread is done (join() then does not block); thread-safe.
  [[nodiscard]] bool finished() const { return finished_.load(); }
  // Precondition: finished(). Whether the session went well.
  [[nodiscard]] bool served_well() const { return outcome_.served.ok(); }
  // Whether a firmware has connected; thread-safe.
  [[nodiscard]] bool connected() const { return connected_.load(); }
  // Stops waiting for a connection (within 100 ms); a session under way goes on until its stream ends.
  void cancel() { cancelled_.store(true); }
  // Waits for the thread; call once.
  [[nodiscard]] Outcome join();

 private:
  void run(plant::Plant& plant, const link::ServeOptions& options, link::Timeout connect_within);

  link::NamedPipes pipes_;
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> connected_{false};
  std::atomic<bool> finished_{false};
  Outcome outcome_;
  std::thread thread_;
};

}  // namespace duet::cli
