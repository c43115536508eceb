#pragma once
// The XCP slave's protocol layer: takes one command packet (CTO) at a time and produces its response. Freestanding:
// no heap, no exceptions; it knows no transport and touches memory only through the MemoryMap it is given.
//
// Call handle() from one context at a time (the transport's receive path). A command handler is one member function
// per command (slave_standard.cpp, slave_calibration.cpp); a table maps command codes to them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "duet/xcp/checksum.hpp"
#include "duet/xcp/daq.hpp"
#include "duet/xcp/memory_map.hpp"
#include "duet/xcp/packet.hpp"
#include "duet/xcp/protocol.hpp"
#include "duet/xcp/transmit_queue.hpp"

namespace duet::xcp {

// Seed & key: the slave makes a seed for a locked resource and checks the key the master computed from it.
struct SeedAndKey {
  // Writes a seed for `resource` into `seed` and returns its length (1 to seed.size()).
  std::size_t (*make_seed)(std::uint8_t resource, std::span<std::uint8_t> seed) = nullptr;
  bool (*key_is_valid)(std::uint8_t resource, std::span<const std::uint8_t> seed,
                       std::span<const std::uint8_t> key) = nullptr;
};

// USER_CMD: gets the request after the command code and writes the positive response's payload (after 0xFF).
// Returns false and sets `error` to refuse it.
using UserCommand = bool (*)(PacketReader& request, PacketWriter& response, Error& error);

// Copies calibration bytes into the model's memory so that no task sees them half-written (a port masks the tasks'
// interrupts, or takes the lock its tasks run under). Without one, the slave copies plainly.
using AtomicWrite = void (*)(std::uint8_t* destination, std::span<const std::uint8_t> bytes);

struct SlaveConfiguration {
  MemoryMap memory{{}};
  std::span<const CalibrationSegment> segments;  // paged calibration memory, looked up before `memory`
  std::uint8_t max_cto = 248;                    // at most 255; a multiple of 8 suits every transport
  std::uint16_t max_dto = 1024;
  // Multi-byte fields of commands, responses and DAQ packets (COMM_MODE_BASIC bit 0). Memory contents are not
  // reordered: they stay as the firmware keeps them (the A2L's BYTE_ORDER says how).
  ByteOrder byte_order = ByteOrder::intel;
  std::string_view identification;    // GET_ID type 1: the A2L file's name without path and extension
  std::span<const std::uint8_t> a2l;  // GET_ID type 4: the A2L itself, if the firmware carries it
  // GET_ID type 5: the EPK, the text the A2L's MOD_PAR names this firmware by. Always through the MTA, as masters
  // that ignore mode 1 for it expect.
  std::string_view epk;
  // GET_ID types 0 and 1 answer with the identification inside the response (mode bit 0) when it fits in MAX_CTO,
  // rather than through the MTA for UPLOAD. The A2L itself always goes through the MTA.
  bool identification_in_response = false;
  ChecksumType checksum_type = ChecksumType::crc_16_ccitt;
  std::uint32_t max_checksum_block = 0x0010'0000;
  std::uint8_t protected_resources = 0;  // locked at every CONNECT until UNLOCK (resource:: bits)
  SeedAndKey seed_and_key;
  UserCommand user_command = nullptr;
  AtomicWrite write_atomically = nullptr;
  // A DOWNLOAD sequence (DOWNLOAD + DOWNLOAD_NEXT ...) is collected here and written at its end, all at once. Its size
  // bounds the sequence; the application owns it.
  std::span<std::uint8_t> download_buffer;

  // DAQ: event channels (the executive's tasks, in task order), the tables' storage, where samples go, and the
  // clock that stamps them (in timestamp_unit_ns nanoseconds per tick). Without storage the slave offers no DAQ.
  std::span<const EventChannel> events;
  DaqStorage daq;
  // How a DAQ packet names its ODT and DAQ list (GET_DAQ_PROCESSOR_INFO's DAQ_KEY_BYTE bits 6-7).
  IdentificationField identification_field = IdentificationField::absolute;
  TransmitQueue* queue = nullptr;
  std::uint32_t (*timestamp)() = nullptr;
  TimestampSize timestamp_size = TimestampSize::dword;  // a DAQ packet carries the clock's low bytes
  std::uint8_t timestamp_unit = 3;                      // 0 = 1 ns, 1 = 10 ns, 2 = 100 ns, 3 = 1 us, ...
  std::uint16_t timestamp_ticks = 1;
};

// What a command handler says: a positive response with the payload it wrote, none at all, or an error code (the
// payload, if any, follows the code).
enum class CommandOutcome : std::uint8_t { positive, silent, negative };
struct CommandResult {
  CommandOutcome outcome = CommandOutcome::positive;
  Error error = Error::generic;
};

class Slave {
 public:
  static constexpr std::size_t max_packet = 255;
  static constexpr std::size_t max_seed = 32;
  // DOWNLOAD_NEXT packets a master may send without waiting (master block mode, GET_COMM_MODE_INFO's MAX_BS).
  static constexpr std::uint8_t max_block_size = 255;

  explicit Slave(const SlaveConfiguration& configuration) : configuration_(configuration) {}

  // Handles one command packet; returns the response to send, or nothing (disconnected, or a DOWNLOAD_NEXT in the
  // middle of a block). The response stays valid until the next call.
  std::span<const std::uint8_t> handle(std::span<const std::uint8_t> command);

  [[nodiscard]] bool connected() const { return connected_; }
  [[nodiscard]] std::uint8_t locked_resources() const { return locked_; }

  // The task of event channel `event` has finished its step: samples every running DAQ list bound to it, whole, into
  // the transmit queue. Interrupt-safe and wait-free; a sample that does not fit is dropped, counted, and announced by
  // an EV_DAQ_OVERLOAD packet before the next sample that fits.
  void on_event(std::uint16_t event);
  [[nodiscard]] std::uint32_t overloads() const { return overloads_.load(std::memory_order_relaxed); }

 private:
  using Outcome = CommandOutcome;
  using Result = CommandResult;
  static constexpr Result ok{};
  static constexpr Result silent{Outcome::silent};
  static constexpr Result fail(Error error) { return {Outcome::negative, error}; }

  using Handler = Result (Slave::*)(PacketReader&, PacketWriter&);
  struct CommandEntry {
    Handler handler = nullptr;
    std::uint8_t minimum_length = 1;  // of the request, command code included
    std::uint8_t resource = 0;        // protected resource the command needs unlocked
  };
  static const std::array<CommandEntry, 0x40>& commands();  // indexed by code - 0xC0

  // Standard commands (slave_standard.cpp).
  Result connect(PacketReader& request, PacketWriter& response);
  Result disconnect(PacketReader& request, PacketWriter& response);
  Result get_status(PacketReader& request, PacketWriter& response);
  Result synch(PacketReader& request, PacketWriter& response);
  Result get_comm_mode_info(PacketReader& request, PacketWriter& response);
  Result get_id(PacketReader& request, PacketWriter& response);
  Result get_seed(PacketReader& request, PacketWriter& response);
  Result unlock(PacketReader& request, PacketWriter& response);
  Result set_mta(PacketReader& request, PacketWriter& response);
  Result upload(PacketReader& request, PacketWriter& response);
  Result short_upload(PacketReader& request, PacketWriter& response);
  Result build_checksum(PacketReader& request, PacketWriter& response);
  Result user_cmd(PacketReader& request, PacketWriter& response);
  // Calibration commands (slave_calibration.cpp).
  Result download(PacketReader& request, PacketWriter& response);
  Result download_next(PacketReader& request, PacketWriter& response);
  Result download_max(PacketReader& request, PacketWriter& response);
  Result short_download(PacketReader& request, PacketWriter& response);
  Result modify_bits(PacketReader& request, PacketWriter& response);
  // Paging commands (slave_paging.cpp).
  Result set_cal_page(PacketReader& request, PacketWriter& response);
  Result get_cal_page(PacketReader& request, PacketWriter& response);
  Result get_pag_processor_info(PacketReader& request, PacketWriter& response);
  Result get_segment_info(PacketReader& request, PacketWriter& response);
  Result get_page_info(PacketReader& request, PacketWriter& response);
  Result set_segment_mode(PacketReader& request, PacketWriter& response);
  Result get_segment_mode(PacketReader& request, PacketWriter& response);
  Result copy_cal_page(PacketReader& request, PacketWriter& response);
  // DAQ commands (slave_daq.cpp).
  Result free_daq(PacketReader& request, PacketWriter& response);
  Result alloc_daq(PacketReader& request, PacketWriter& response);
  Result alloc_odt(PacketReader& request, PacketWriter& response);
  Result alloc_odt_entry(PacketReader& request, PacketWriter& response);
  Result set_daq_ptr(PacketReader& request, PacketWriter& response);
  Result write_daq(PacketReader& request, PacketWriter& response);
  Result write_daq_multiple(PacketReader& request, PacketWriter& response);
  Result read_daq(PacketReader& request, PacketWriter& response);
  Result clear_daq_list(PacketReader& request, PacketWriter& response);
  Result set_daq_list_mode(PacketReader& request, PacketWriter& response);
  Result get_daq_list_mode(PacketReader& request, PacketWriter& response);
  Result start_stop_daq_list(PacketReader& request, PacketWriter& response);
  Result start_stop_synch(PacketReader& request, PacketWriter& response);
  Result get_daq_clock(PacketReader& request, PacketWriter& response);
  Result get_daq_processor_info(PacketReader& request, PacketWriter& response);
  Result get_daq_resolution_info(PacketReader& request, PacketWriter& response);
  Result get_daq_event_info(PacketReader& request, PacketWriter& response);
  Result get_daq_list_info(PacketReader& request, PacketWriter& response);

  // The memory transfer address: a place in the memory map, or an identification GET_ID pointed at.
  struct TransferAddress {
    std::uint8_t extension = 0;
    std::uint32_t address = 0;
    std::span<const std::uint8_t> identification;  // when not empty, UPLOAD reads from here
    bool points_to_identification = false;
  };

  // Where the DAQ allocation sequence stands: FREE_DAQ, then ALLOC_DAQ, then ALLOC_ODT, then ALLOC_ODT_ENTRY.
  enum class DaqAllocation : std::uint8_t { freed, lists, odts, entries };
  Result write_daq_entry(std::uint8_t bit_offset, std::uint8_t size, std::uint8_t extension, std::uint32_t address);
  [[nodiscard]] bool daq_running() const;
  void stop_all_daq();
  [[nodiscard]] std::size_t odt_payload(const DaqList& list, std::size_t odt_index) const;
  // Samples every running DAQ list of `event`; `make_header` gives what begins each sample's packets.
  template <typename MakeHeader>
  void sample_event(std::uint16_t event, MakeHeader make_header);
  static void sample_in_usual_layout(Slave& slave, std::uint16_t event);  // absolute ODT numbers, 4-byte Intel stamps
  static void sample_in_other_layout(Slave& slave, std::uint16_t event);
  static void sample_nothing(Slave& slave, std::uint16_t event);
  // The largest entry WRITE_DAQ takes: what fits a sample's first packet (duet/xcp/daq.hpp).
  [[nodiscard]] std::uint8_t max_entry_size() const;

  // Memory at an XCP address: a calibration segment's page XCP chose, else a declared region; nullptr if neither
  // holds all `size` bytes (readable, or writable).
  [[nodiscard]] const std::uint8_t* readable_memory(std::uint8_t extension, std::uint32_t address,
                                                    std::uint32_t size) const;
  [[nodiscard]] std::uint8_t* writable_memory(std::uint8_t extension, std::uint32_t address, std::uint32_t size) const;
  const CalibrationSegment* segment_at(std::uint8_t extension, std::uint32_t address, std::uint32_t size,
                                       std::size_t& index) const;
  static constexpr std::size_t max_segments = 16;

  Result read_at_mta(std::uint32_t count, PacketWriter& response);
  Result write_at_mta(std::span<const std::uint8_t> bytes);
  void write_memory(std::uint8_t* destination, std::span<const std::uint8_t> bytes) const;
  void reset_session();

  const SlaveConfiguration& configuration_;
  bool connected_ = false;
  std::uint8_t locked_ = 0;
  TransferAddress mta_;
  // Seed & key in progress.
  std::uint8_t seed_resource_ = 0;
  std::array<std::uint8_t, max_seed> seed_{};
  std::size_t seed_length_ = 0;
  std::size_t seed_sent_ = 0;
  std::array<std::uint8_t, max_seed> key_{};
  std::size_t key_received_ = 0;
  std::size_t key_length_ = 0;
  // DOWNLOAD sequence in progress: bytes still expected, bytes collected.
  std::uint32_t download_remaining_ = 0;
  std::size_t download_collected_ = 0;
  // DAQ tables in use, and the DAQ pointer of SET_DAQ_PTR / WRITE_DAQ.
  DaqAllocation daq_allocation_ = DaqAllocation::freed;
  std::uint16_t daq_lists_ = 0;
  std::uint16_t daq_odts_ = 0;
  std::uint16_t daq_entries_ = 0;
  std::uint16_t daq_pointer_list_ = 0;
  std::uint16_t daq_pointer_entry_ = 0;  // absolute entry index
  std::uint16_t daq_pointer_end_ = 0;    // one past the ODT's last entry; equal to the pointer when not set
  std::array<std::uint8_t, max_segments> xcp_page_{};  // per segment: the page XCP reads and writes
  // on_event()'s sampling loop for the configured DAQ packet layout (chosen at CONNECT, when the queue is known).
  std::atomic<void (*)(Slave&, std::uint16_t)> sample_{sample_nothing};
  std::atomic<bool> overload_pending_{false};
  std::atomic<std::uint32_t> overloads_{0};
  std::array<std::uint8_t, max_packet + 1> response_{};
};

}  // namespace duet::xcp
