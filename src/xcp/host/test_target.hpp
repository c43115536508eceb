#pragma once
// A slave on the PC for tests: signals, parameters with two pages, DAQ storage, seed & key on DAQ (the key is the
// seed's complement), an XCP-on-Ethernet server, a clock, and a step() that plays a model: event 0 every step,
// event 1 every second step, the clock `ticks_per_step` further each step. Test code only.

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <span>
#include <vector>

#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"

namespace duet::xcp::host {

inline std::mutex test_queue_mutex;
inline std::uint32_t lock_test_queue() {
  test_queue_mutex.lock();
  return 0;
}
inline void unlock_test_queue(std::uint32_t) { test_queue_mutex.unlock(); }

// The slave's clock (a timestamp function has no context, so there is one clock per process).
inline std::atomic<std::uint32_t> test_target_clock{0};
inline std::uint32_t read_test_target_clock() { return test_target_clock.load(std::memory_order_relaxed); }

inline std::size_t make_seed(std::uint8_t, std::span<std::uint8_t> seed) {
  for (std::size_t byte = 0; byte < 8; ++byte) seed[byte] = static_cast<std::uint8_t>(0xA0 + byte);
  return 8;
}
inline bool key_is_valid(std::uint8_t, std::span<const std::uint8_t> seed, std::span<const std::uint8_t> key) {
  if (key.size() != seed.size()) return false;
  for (std::size_t byte = 0; byte < key.size(); ++byte) {
    if (key[byte] != static_cast<std::uint8_t>(~seed[byte])) return false;
  }
  return true;
}
inline std::vector<std::uint8_t> compute_key(std::uint8_t, std::span<const std::uint8_t> seed) {
  std::vector<std::uint8_t> key;
  for (std::uint8_t byte : seed) key.push_back(static_cast<std::uint8_t>(~byte));
  return key;
}

struct TestTarget {
  explicit TestTarget(std::uint8_t protected_resources = resource::daq) {
    configuration.protected_resources = protected_resources;
  }

  struct Signals {
    std::uint32_t counter;
    std::uint16_t twice;
    std::uint8_t slow;
  };
  Signals signals{};
  std::array<std::uint8_t, 8> parameters{};
  std::array<std::uint8_t, 8> reference{1, 2, 3, 4, 5, 6, 7, 8};
  const std::uint8_t* volatile ecu_page = parameters.data();
  std::array<char, 14> epk{"duet_target 1"};  // what its A2L names it by
  std::array<MemoryRegion, 2> regions{
      MemoryRegion{.name = "signals",
                   .address = 0x1000,
                   .size = sizeof(Signals),
                   .memory = reinterpret_cast<std::uint8_t*>(&signals)},
      MemoryRegion{
          .name = "epk", .address = 0x4000, .size = 13, .memory = reinterpret_cast<std::uint8_t*>(epk.data())}};
  std::array<CalibrationSegment, 1> segments{CalibrationSegment{.name = "parameters",
                                                                .address = 0x2000,
                                                                .size = 8,
                                                                .working = parameters.data(),
                                                                .reference = reference.data(),
                                                                .ecu_page = &ecu_page}};
  std::array<EventChannel, 2> events{EventChannel{.name = "1 ms"}, EventChannel{.name = "10 ms"}};
  std::array<DaqList, 4> lists{};
  std::array<Odt, 8> odts{};
  std::array<OdtEntry, 16> entries{};
  std::array<std::uint8_t, 1 << 16> queue_storage{};
  std::array<std::uint8_t, 256> download_buffer{};
  TransmitQueue queue{queue_storage, {lock_test_queue, unlock_test_queue}};
  SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                   .segments = segments,
                                   .max_cto = 32,
                                   .max_dto = 64,
                                   .identification = "duet_target",
                                   .seed_and_key = {make_seed, key_is_valid},
                                   .download_buffer = download_buffer,
                                   .events = events,
                                   .daq = {lists, odts, entries},
                                   .queue = &queue,
                                   .timestamp = read_test_target_clock};
  // The clock at step n is clock_start + n * ticks_per_step (wrapping at 32 bits): 1 ms per step in 1 us ticks.
  std::uint32_t clock_start = 0;
  std::uint32_t ticks_per_step = 1000;
  Slave slave{configuration};
  std::mutex model_mutex;  // the model's tasks run under it; the server's commands too
  SlaveServer server{slave, queue, [this](const std::function<void()>& work) {
                       const std::lock_guard lock{model_mutex};
                       work();
                     }};

  // One model step: the 1 ms event every step, the 10 ms event every second step.
  void step(std::uint32_t number) {
    {
      const std::lock_guard lock{model_mutex};
      test_target_clock.store(clock_start + number * ticks_per_step, std::memory_order_relaxed);
      signals.counter = number;
      signals.twice = static_cast<std::uint16_t>(2 * number);
      slave.on_event(0);
      if (number % 2 == 0) {
        signals.slow = static_cast<std::uint8_t>(number / 2);
        slave.on_event(1);
      }
    }
    server.notify();
  }

  // The A2L of this target, reached at `transport`.
  static A2lDescription a2l(const Endpoint& transport) {
    A2lDescription description;
    description.module = "test_target";
    description.memory = {{"signals", 0, 0x1000, 8, false}, {"parameters", 0, 0x2000, 8, true}};
    description.measurements = {{"counter", "step number", DataType::uint32, 0, 0x1000, 1, "", 0, 4294967295.0, {}},
                                {"twice", "twice the step", DataType::uint16, 0, 0x1004, 1, "", 0, 65535, {}},
                                {"slow", "every second step", DataType::uint8, 0, 0x1006, 1, "", 0, 255, {}}};
    description.characteristics = {
        {"gain", "a gain", DataType::float32, 0, 0x2000, 1, "", 0, 100, {}},
        {"scaled", "a scaled word", DataType::uint16, 0, 0x2004, 1, "V", 0, 10, {0.01, 0}},
        {"flags", "two bytes", DataType::uint8, 0, 0x2006, 2, "", 0, 255, {}, {{0, "clear"}, {1, "set"}}}};
    description.events = {{"1 ms", 0, 1, 6, 0}, {"10 ms", 1, 10, 6, 0}};
    description.max_cto = 32;
    description.max_dto = 64;
    description.epk = "duet_target 1";
    description.epk_address = 0x4000;
    description.transport = transport;
    return description;
  }
};

}  // namespace duet::xcp::host
