#pragma once
// Software in the loop on the PC: the robot's generated firmware (generated/balbot.hpp, balbot::description) on the
// host's lock-step executive, its hardware calls (duet::hardware) connected to a plant: the simulated robot in this
// process, or a duet::link::RemotePlant that reaches `duet plant serve balbot` in another. Each base tick the plant
// moves to the tick's time first, raising interrupts by name, each of which runs the firmware's interrupt task of
// that name at once; then the executive runs the tick's periodic steps. This is the order duet sim keeps, so against
// the same plant a run records what duet sim records for balbot.yaml, bit for bit.

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>

#include "duet/link/pacer.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"
#include "sil_measurements.hpp"

namespace duet::sil {

struct SilOptions {
  // Simulated time: ticks 0 to floor(duration / base period), as duet sim counts them.
  double duration_s = 10;
  // Real time: wait before each tick until the wall clock reaches its time (a plant in this process; a RemotePlant
  // in real-time mode paces itself). None: lock-step, as fast as the PC goes.
  link::Pacer* pacer = nullptr;
  // Record these measurements after every tick (none: record nothing).
  const Measurements* measurements = nullptr;
  // Asked after every tick; a failure ends the run with it (a RemotePlant whose link broke: its status()).
  std::function<Status()> check;
  // The firmware's XCP slave (sil_xcp.hpp): held for each tick, so that its server reaches the firmware's memory
  // only between ticks; told each tick's time before it runs and each task that finished (the task's event).
  std::mutex* memory_lock = nullptr;
  std::function<void(double now_s)> tick_started;
  std::function<void(std::size_t task)> task_finished;
};

struct SilResult {
  std::uint64_t ticks = 0;
  double final_theta_deg = 0;  // the firmware's Kalman-filtered tilt after the last tick
  // The largest |theta| from 4 s on (the release at 2 s has settled by then); none when the run is shorter.
  std::optional<double> largest_theta_after_4_s_deg;
  model::Recording recording;  // empty without SilOptions::measurements
};

// The firmware's state is global (the generated `memory`): one run at a time per process. Each run starts it afresh
// (signals zeroed, the model's parameters, initialize()), so runs in one process are alike. Blocks for the run;
// `plant` must not be used by anything else meanwhile.
[[nodiscard]] Result<SilResult> run_sil(plant::Plant& plant, const SilOptions& options);

// The firmware's measurements as its generated A2L (DUET_BALBOT_A2L, read at run time) describes them.
[[nodiscard]] Result<Measurements> balbot_measurements();

}  // namespace duet::sil
