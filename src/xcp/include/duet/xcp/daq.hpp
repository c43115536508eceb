#pragma once
// DAQ (data acquisition) tables with dynamic configuration: the master allocates DAQ lists, their ODTs (one packet
// each) and the ODTs' entries (address, size) at run time, in storage the application sizes at build time. Each DAQ
// list is bound to an event channel: one of the executive's tasks, which samples the list right after its step.

#include <atomic>
#include <cstdint>
#include <span>
#include <string_view>

namespace duet::xcp {

// How a DAQ packet says which ODT of which DAQ list it carries (GET_DAQ_PROCESSOR_INFO's DAQ_KEY_BYTE bits 6-7, the
// A2L's IDENTIFICATION_FIELD_TYPE_*): the absolute ODT number in one byte, or the ODT number relative to its list
// followed by the list number as a byte, a word, or a word after a fill byte (aligned).
enum class IdentificationField : std::uint8_t {
  absolute = 0,
  relative_byte = 1,
  relative_word = 2,
  relative_word_aligned = 3
};

// Bytes the identification field takes at the start of every DAQ packet.
constexpr std::size_t identification_size(IdentificationField field) { return static_cast<std::size_t>(field) + 1; }

// Bytes of the slave's clock in the first DAQ packet of a sample (GET_DAQ_RESOLUTION_INFO's TIMESTAMP_MODE bits 0-2).
enum class TimestampSize : std::uint8_t { byte = 1, word = 2, dword = 4 };

// The largest ODT entry a slave samples (GET_DAQ_RESOLUTION_INFO's and the A2L's MAX_ODT_ENTRY_SIZE_DAQ): what fits
// the first packet of a sample after its identification and timestamp, at most a byte's worth. The slave answers it
// and duet gen writes it into the A2L, from this one place.
constexpr std::uint8_t max_odt_entry_size(std::size_t max_dto, IdentificationField field, TimestampSize timestamp) {
  const std::size_t room = max_dto - identification_size(field) - static_cast<std::size_t>(timestamp);
  return static_cast<std::uint8_t>(room > 0xFF ? 0xFF : room);
}

// An event channel, as GET_DAQ_EVENT_INFO and the A2L describe it.
struct EventChannel {
  std::string_view name;
  std::uint8_t time_cycle = 0;  // the period in time_unit; 0 for an event without a period (an interrupt)
  std::uint8_t time_unit = 0;   // 0 = 1 ns, 1 = 10 ns, ... 9 = 1 s (as the timestamp unit)
  std::uint8_t priority = 0;    // 0 lowest ... 255 highest
};

struct OdtEntry {
  const std::uint8_t* memory = nullptr;  // resolved and checked against the memory map at WRITE_DAQ
  std::uint32_t address = 0;             // as the master wrote it, for READ_DAQ
  std::uint8_t extension = 0;
  std::uint8_t size = 0;  // 0: not written yet
};

struct Odt {
  std::uint16_t first_entry = 0;
  std::uint8_t entry_count = 0;
  std::uint16_t packet_size = 0;  // PID, timestamp if any, entries: fixed when its list starts
  // The size all its entries share, 0 if they differ (fixed with packet_size): four-byte signals, the usual case, are
  // copied by a loop that reads no sizes.
  std::uint8_t entry_size = 0;
};

struct DaqList {
  std::uint16_t first_odt = 0;
  std::uint8_t odt_count = 0;
  std::uint8_t mode = 0;  // SET_DAQ_LIST_MODE's bits the slave keeps (timestamp)
  std::uint16_t event = 0;
  bool event_set = false;
  std::uint8_t prescaler = 1;
  std::uint8_t priority = 0;
  std::uint8_t prescaler_count = 0;  // the event's own context only
  std::uint32_t sample_bytes = 0;    // what one sample's records take in the transmit queue: fixed when it starts
  bool selected = false;
  std::atomic<bool> running{false};
};

// The application's storage for the tables: sizes are its build-time choice.
struct DaqStorage {
  std::span<DaqList> lists;
  std::span<Odt> odts;
  std::span<OdtEntry> entries;
};

// SET_DAQ_LIST_MODE and GET_DAQ_LIST_MODE bits.
namespace daq_mode {
inline constexpr std::uint8_t selected = 0x01;
inline constexpr std::uint8_t direction_stim = 0x02;
inline constexpr std::uint8_t dto_counter = 0x08;
inline constexpr std::uint8_t timestamp = 0x10;
inline constexpr std::uint8_t pid_off = 0x20;
inline constexpr std::uint8_t running = 0x40;
inline constexpr std::uint8_t resume = 0x80;
}  // namespace daq_mode

}  // namespace duet::xcp
