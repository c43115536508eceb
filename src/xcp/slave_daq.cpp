// The slave's DAQ commands (dynamic configuration) and the sampling that event channels trigger.
//
// Identification: as the firmware configures it (IdentificationField). With absolute ODT numbers the PID is the
// ODT's index in the storage, so at most 0xFC ODTs; with relative ones each list has up to 0xFC ODTs and its number
// follows the ODT's. The first ODT of a sample carries the clock's low bytes (1, 2 or 4) after the identification
// when the list asks for timestamps. Overload is announced with EV_DAQ_OVERLOAD.

#include "duet/base/shared_order.hpp"
#include "duet/xcp/slave.hpp"

namespace duet::xcp {
namespace {

constexpr std::size_t max_odt_number = 0xFC;  // identification bytes below RES/ERR/EV/SERV
constexpr std::size_t max_byte_lists = 0x100;
constexpr std::uint8_t no_bit_offset = 0xFF;
// GET_DAQ_PROCESSOR_INFO: dynamic configuration, prescaler, timestamps; overload indicated by an event (bits 6-7 = 2).
constexpr std::uint8_t daq_properties = 0x01 | 0x02 | 0x10 | 0x80;
// GET_DAQ_EVENT_INFO: a DAQ event whose samples are consistent per event (bits 6-7 = 2).
constexpr std::uint8_t event_properties = 0x04 | 0x80;
constexpr std::uint8_t list_properties_daq = 0x04;

// How a sample's packets begin. The usual layout (absolute ODT number, 4-byte Intel timestamp) is written directly,
// as fast as before the layouts were configurable; any other is encoded once per sample and copied.
struct AbsoluteIntelHeader {
  const DaqList& list;
  std::uint32_t now = 0;

  template <typename Out>
  void identification(Out& out, std::size_t odt) const {
    out.u8(static_cast<std::uint8_t>(list.first_odt + odt));
  }
  template <typename Out>
  void timestamp(Out& out) const {
    out.u32(now);
  }
};

struct EncodedHeader {
  EncodedHeader(const SlaveConfiguration& configuration, std::uint16_t list, std::uint16_t list_first_odt,
                std::uint32_t now)
      : absolute(configuration.identification_field == IdentificationField::absolute),
        first_odt(list_first_odt),
        field_size(identification_size(configuration.identification_field)),
        stamp_size(static_cast<std::size_t>(configuration.timestamp_size)) {
    const bool intel = configuration.byte_order == ByteOrder::intel;
    // The list number after the ODT number: a byte, a word, or a fill byte and a word.
    const auto low = static_cast<std::uint8_t>(list);
    const auto high = static_cast<std::uint8_t>(list >> 8U);
    if (configuration.identification_field == IdentificationField::relative_byte) {
      field[1] = low;
    } else if (!absolute) {
      const std::size_t at = configuration.identification_field == IdentificationField::relative_word_aligned ? 2 : 1;
      field[at] = intel ? low : high;
      field[at + 1] = intel ? high : low;
    }
    // The clock's low bytes.
    for (std::size_t byte = 0; byte < stamp_size; ++byte) {
      const std::size_t significance = intel ? byte : stamp_size - 1 - byte;
      stamp[byte] = static_cast<std::uint8_t>(now >> (8U * significance));
    }
  }

  template <typename Out>
  void identification(Out& out, std::size_t odt) const {
    out.u8(static_cast<std::uint8_t>(absolute ? first_odt + odt : odt));
    for (std::size_t byte = 1; byte < field_size; ++byte) out.u8(field[byte]);
  }
  template <typename Out>
  void timestamp(Out& out) const {
    for (std::size_t byte = 0; byte < stamp_size; ++byte) out.u8(stamp[byte]);
  }

  bool absolute;
  std::uint16_t first_odt;
  std::size_t field_size;
  std::size_t stamp_size;
  std::array<std::uint8_t, 4> field{};
  std::array<std::uint8_t, 4> stamp{};
};
// EV_DAQ_OVERLOAD's packet.
constexpr std::size_t overload_packet = 2;

// Writes one ODT's packet: its header, the timestamp if `stamped`, its entries.
template <typename Out, typename Header>
[[gnu::always_inline]] inline void write_odt(Out& out, const DaqStorage& daq, const Odt& target, const Header& header,
                                             std::size_t odt, bool stamped) {
  out.packet(target.packet_size);
  header.identification(out, odt);
  if (stamped) header.timestamp(out);
  const OdtEntry* entry = &daq.entries[target.first_entry];
  if (target.entry_size == 4) {
    // Three instructions an entry, eight entries a round, then four, then one at a time: counted rounds, where a
    // loop over the entries' range had the compiler divide the range by the entry's size to enter its unrolled body.
    for (std::size_t rounds = target.entry_count / 8U; rounds != 0; --rounds, entry += 8) {
      out.bytes(entry[0].memory, 4).bytes(entry[1].memory, 4).bytes(entry[2].memory, 4).bytes(entry[3].memory, 4);
      out.bytes(entry[4].memory, 4).bytes(entry[5].memory, 4).bytes(entry[6].memory, 4).bytes(entry[7].memory, 4);
    }
    for (std::size_t rest = target.entry_count % 8U; rest != 0; --rest, ++entry) out.bytes(entry->memory, 4);
  } else {
    for (const OdtEntry* const end = entry + target.entry_count; entry != end; ++entry)
      out.bytes(entry->memory, entry->size);
  }
}

// Queues one sample of `list` (whose ODTs begin at `first`) whole, after EV_DAQ_OVERLOAD if one is due, or nothing
// if it does not fit.
template <typename Header>
bool queue_sample(TransmitQueue& queue, const DaqStorage& daq, const DaqList& list, const Odt* first,
                  std::size_t record_bytes, bool stamped, const Header& header, bool announce_overload,
                  std::size_t headroom) {
  if (list.odt_count == 1 && !announce_overload) {
    // The usual sample, one packet: without the loop and the announcement, whose values the compiler would otherwise
    // keep on the stack across the queue's lock (22 instructions of a DAQ event's 243).
    return queue.push(record_bytes, headroom, [&](auto& out) { write_odt(out, daq, *first, header, 0, stamped); });
  }
  return queue.push(record_bytes, headroom, [&](auto& out) {
    if (announce_overload)
      out.packet(overload_packet).u8(pid::event).u8(static_cast<std::uint8_t>(EventCode::daq_overload));
    for (std::size_t odt = 0; odt < list.odt_count; ++odt)
      write_odt(out, daq, first[odt], header, odt, odt == 0 && stamped);
  });
}

}  // namespace

bool Slave::daq_running() const {
  for (std::size_t list = 0; list < daq_lists_; ++list) {
    if (configuration_.daq.lists[list].running.load(std::memory_order_relaxed)) return true;
  }
  return false;
}

void Slave::stop_all_daq() {
  for (std::size_t list = 0; list < daq_lists_; ++list) {
    configuration_.daq.lists[list].running.store(false, std::memory_order_relaxed);
    configuration_.daq.lists[list].selected = false;
  }
}

std::uint8_t Slave::max_entry_size() const {
  return max_odt_entry_size(configuration_.max_dto, configuration_.identification_field, configuration_.timestamp_size);
}

std::size_t Slave::odt_payload(const DaqList& list, std::size_t odt_index) const {
  const Odt& odt = configuration_.daq.odts[list.first_odt + odt_index];
  const bool stamped = odt_index == 0 && (list.mode & daq_mode::timestamp) != 0;
  std::size_t size = identification_size(configuration_.identification_field) +
                     (stamped ? static_cast<std::size_t>(configuration_.timestamp_size) : 0);
  for (std::size_t entry = 0; entry < odt.entry_count; ++entry)
    size += configuration_.daq.entries[odt.first_entry + entry].size;
  return size;
}

Slave::Result Slave::free_daq(PacketReader&, PacketWriter&) {
  stop_all_daq();
  daq_lists_ = daq_odts_ = daq_entries_ = 0;
  daq_pointer_entry_ = daq_pointer_end_ = 0;
  daq_allocation_ = DaqAllocation::freed;
  return ok;
}

Slave::Result Slave::alloc_daq(PacketReader& request, PacketWriter&) {
  request.skip(1);
  const std::uint16_t count = request.u16();
  if (daq_allocation_ != DaqAllocation::freed) return fail(Error::sequence);
  const bool numbered_by_byte = configuration_.identification_field == IdentificationField::relative_byte;
  if (count > configuration_.daq.lists.size() || (numbered_by_byte && count > max_byte_lists)) {
    return fail(Error::memory_overflow);
  }
  for (std::size_t list = 0; list < count; ++list) {
    DaqList& daq_list = configuration_.daq.lists[list];
    daq_list.running.store(false, std::memory_order_relaxed);
    daq_list.first_odt = 0;
    daq_list.odt_count = 0;
    daq_list.mode = 0;
    daq_list.event_set = false;
    daq_list.prescaler = 1;
    daq_list.prescaler_count = 0;
    daq_list.selected = false;
  }
  daq_lists_ = count;
  daq_allocation_ = DaqAllocation::lists;
  return ok;
}

Slave::Result Slave::alloc_odt(PacketReader& request, PacketWriter&) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  const std::uint8_t count = request.u8();
  if (daq_allocation_ != DaqAllocation::lists && daq_allocation_ != DaqAllocation::odts) return fail(Error::sequence);
  if (list >= daq_lists_) return fail(Error::out_of_range);
  DaqList& daq_list = configuration_.daq.lists[list];
  if (daq_list.odt_count != 0) return fail(Error::sequence);  // each list gets its ODTs once
  // Absolute ODT numbers count all lists' ODTs; relative ones each list's own.
  const bool absolute = configuration_.identification_field == IdentificationField::absolute;
  const std::size_t storage = configuration_.daq.odts.size();
  const std::size_t capacity = absolute && storage > max_odt_number ? max_odt_number : storage;
  if (count == 0 || count > max_odt_number || daq_odts_ + count > capacity) return fail(Error::memory_overflow);
  daq_list.first_odt = daq_odts_;
  daq_list.odt_count = count;
  for (std::size_t odt = daq_odts_; odt < daq_odts_ + count; ++odt) configuration_.daq.odts[odt] = {};
  daq_odts_ = static_cast<std::uint16_t>(daq_odts_ + count);
  daq_allocation_ = DaqAllocation::odts;
  return ok;
}

Slave::Result Slave::alloc_odt_entry(PacketReader& request, PacketWriter&) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  const std::uint8_t odt = request.u8();
  const std::uint8_t count = request.u8();
  if (daq_allocation_ != DaqAllocation::odts && daq_allocation_ != DaqAllocation::entries) return fail(Error::sequence);
  if (list >= daq_lists_ || odt >= configuration_.daq.lists[list].odt_count) return fail(Error::out_of_range);
  Odt& target = configuration_.daq.odts[configuration_.daq.lists[list].first_odt + odt];
  if (target.entry_count != 0) return fail(Error::sequence);
  if (count == 0 || daq_entries_ + count > configuration_.daq.entries.size()) return fail(Error::memory_overflow);
  target.first_entry = daq_entries_;
  target.entry_count = count;
  for (std::size_t entry = daq_entries_; entry < daq_entries_ + count; ++entry) configuration_.daq.entries[entry] = {};
  daq_entries_ = static_cast<std::uint16_t>(daq_entries_ + count);
  daq_allocation_ = DaqAllocation::entries;
  return ok;
}

Slave::Result Slave::set_daq_ptr(PacketReader& request, PacketWriter&) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  const std::uint8_t odt = request.u8();
  const std::uint8_t entry = request.u8();
  if (list >= daq_lists_) return fail(Error::out_of_range);
  const DaqList& daq_list = configuration_.daq.lists[list];
  if (odt >= daq_list.odt_count) return fail(Error::out_of_range);
  const Odt& target = configuration_.daq.odts[daq_list.first_odt + odt];
  if (entry >= target.entry_count) return fail(Error::out_of_range);
  if (daq_list.running.load(std::memory_order_relaxed)) return fail(Error::daq_active);
  daq_pointer_list_ = list;
  daq_pointer_entry_ = static_cast<std::uint16_t>(target.first_entry + entry);
  daq_pointer_end_ = static_cast<std::uint16_t>(target.first_entry + target.entry_count);
  return ok;
}

Slave::Result Slave::write_daq_entry(std::uint8_t bit_offset, std::uint8_t size, std::uint8_t extension,
                                     std::uint32_t address) {
  if (daq_pointer_entry_ >= daq_pointer_end_) return fail(Error::sequence);  // no pointer, or past the ODT's end
  if (configuration_.daq.lists[daq_pointer_list_].running.load(std::memory_order_relaxed)) {
    return fail(Error::daq_active);
  }
  if (bit_offset != no_bit_offset || size == 0 || size > max_entry_size()) {
    return fail(Error::out_of_range);
  }
  const std::uint8_t* memory = readable_memory(extension, address, size);
  if (memory == nullptr) return fail(Error::access_denied);
  configuration_.daq.entries[daq_pointer_entry_++] = {memory, address, extension, size};
  return ok;
}

Slave::Result Slave::write_daq(PacketReader& request, PacketWriter&) {
  const std::uint8_t bit_offset = request.u8();
  const std::uint8_t size = request.u8();
  const std::uint8_t extension = request.u8();
  return write_daq_entry(bit_offset, size, extension, request.u32());
}

// Elements of 8 bytes: bit offset, size, address (4), extension, fill.
Slave::Result Slave::write_daq_multiple(PacketReader& request, PacketWriter&) {
  const std::uint8_t count = request.u8();
  if (count == 0 || request.remaining() != static_cast<std::size_t>(count) * 8U) return fail(Error::cmd_syntax);
  for (std::size_t element = 0; element < count; ++element) {
    const std::uint8_t bit_offset = request.u8();
    const std::uint8_t size = request.u8();
    const std::uint32_t address = request.u32();
    const std::uint8_t extension = request.u8();
    request.skip(1);
    if (const Result result = write_daq_entry(bit_offset, size, extension, address);
        result.outcome != Outcome::positive) {
      return result;
    }
  }
  return ok;
}

Slave::Result Slave::read_daq(PacketReader&, PacketWriter& response) {
  if (daq_pointer_entry_ >= daq_pointer_end_) return fail(Error::sequence);
  const OdtEntry& entry = configuration_.daq.entries[daq_pointer_entry_++];
  response.u8(no_bit_offset).u8(entry.size).u8(entry.extension).u32(entry.address);
  return ok;
}

Slave::Result Slave::clear_daq_list(PacketReader& request, PacketWriter&) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  if (list >= daq_lists_) return fail(Error::out_of_range);
  DaqList& daq_list = configuration_.daq.lists[list];
  daq_list.running.store(false, std::memory_order_relaxed);
  daq_list.selected = false;
  for (std::size_t odt = 0; odt < daq_list.odt_count; ++odt) {
    const Odt& target = configuration_.daq.odts[daq_list.first_odt + odt];
    for (std::size_t entry = 0; entry < target.entry_count; ++entry)
      configuration_.daq.entries[target.first_entry + entry] = {};
  }
  return ok;
}

Slave::Result Slave::set_daq_list_mode(PacketReader& request, PacketWriter&) {
  const std::uint8_t mode = request.u8();
  const std::uint16_t list = request.u16();
  const std::uint16_t event = request.u16();
  const std::uint8_t prescaler = request.u8();
  const std::uint8_t priority = request.u8();
  if (list >= daq_lists_ || event >= configuration_.events.size() || prescaler == 0) return fail(Error::out_of_range);
  constexpr std::uint8_t unsupported = daq_mode::direction_stim | daq_mode::dto_counter | daq_mode::pid_off;
  if ((mode & unsupported) != 0) return fail(Error::mode_not_valid);
  DaqList& daq_list = configuration_.daq.lists[list];
  if (daq_list.running.load(std::memory_order_relaxed)) return fail(Error::daq_active);
  daq_list.mode = static_cast<std::uint8_t>(mode & daq_mode::timestamp);
  daq_list.event = event;
  daq_list.event_set = true;
  daq_list.prescaler = prescaler;
  daq_list.prescaler_count = 0;
  daq_list.priority = priority;
  return ok;
}

Slave::Result Slave::get_daq_list_mode(PacketReader& request, PacketWriter& response) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  if (list >= daq_lists_) return fail(Error::out_of_range);
  const DaqList& daq_list = configuration_.daq.lists[list];
  std::uint8_t mode = daq_list.mode;
  if (daq_list.selected) mode |= daq_mode::selected;
  if (daq_list.running.load(std::memory_order_relaxed)) mode |= daq_mode::running;
  response.u8(mode).u16(0).u16(daq_list.event).u8(daq_list.prescaler).u8(daq_list.priority);
  return ok;
}

Slave::Result Slave::start_stop_daq_list(PacketReader& request, PacketWriter& response) {
  const std::uint8_t mode = request.u8();
  const std::uint16_t list = request.u16();
  if (list >= daq_lists_ || mode > 2) return fail(Error::out_of_range);
  DaqList& daq_list = configuration_.daq.lists[list];
  if (mode != 0) {  // start or select: the list must be complete and fit MAX_DTO
    if (!daq_list.event_set || daq_list.odt_count == 0) return fail(Error::daq_config);
    for (std::size_t odt = 0; odt < daq_list.odt_count; ++odt) {
      const Odt& target = configuration_.daq.odts[daq_list.first_odt + odt];
      for (std::size_t entry = 0; entry < target.entry_count; ++entry) {
        if (configuration_.daq.entries[target.first_entry + entry].size == 0) return fail(Error::daq_config);
      }
      if (odt_payload(daq_list, odt) > configuration_.max_dto) return fail(Error::daq_config);
    }
    std::size_t sample_bytes = 0;
    for (std::size_t odt = 0; odt < daq_list.odt_count; ++odt) {
      Odt& target = configuration_.daq.odts[daq_list.first_odt + odt];
      target.packet_size = static_cast<std::uint16_t>(odt_payload(daq_list, odt));
      target.entry_size = configuration_.daq.entries[target.first_entry].size;
      for (std::size_t entry = 1; entry < target.entry_count; ++entry) {
        if (configuration_.daq.entries[target.first_entry + entry].size != target.entry_size) target.entry_size = 0;
      }
      sample_bytes += TransmitQueue::record_header + target.packet_size;
    }
    daq_list.sample_bytes = static_cast<std::uint32_t>(sample_bytes);
  }
  switch (mode) {
    case 0: daq_list.running.store(false, std::memory_order_relaxed); break;
    case 1:
      daq_list.prescaler_count = 0;
      store_release(daq_list.running, true);
      break;
    default: daq_list.selected = true; break;
  }
  // FIRST_PID: the identification of the list's first packet with absolute ODT numbers; with relative ones the first
  // ODT's number is always 0.
  const bool absolute = configuration_.identification_field == IdentificationField::absolute;
  response.u8(absolute ? static_cast<std::uint8_t>(daq_list.first_odt) : 0);
  return ok;
}

Slave::Result Slave::start_stop_synch(PacketReader& request, PacketWriter&) {
  const std::uint8_t mode = request.u8();
  if (mode > 2) return fail(Error::out_of_range);
  for (std::size_t list = 0; list < daq_lists_; ++list) {
    DaqList& daq_list = configuration_.daq.lists[list];
    if (mode == 0) {
      daq_list.running.store(false, std::memory_order_relaxed);
    } else if (daq_list.selected) {
      if (mode == 1) daq_list.prescaler_count = 0;
      store_release(daq_list.running, mode == 1);
    }
    if (mode != 0) daq_list.selected = false;
  }
  return ok;
}

// NOLINTNEXTLINE(readability-make-member-function-const): every handler has the table's signature
Slave::Result Slave::get_daq_clock(PacketReader&, PacketWriter& response) {
  const std::uint32_t now = configuration_.timestamp != nullptr ? configuration_.timestamp() : 0;
  response.u8(0).u8(0).u8(0).u32(now);  // reserved, trigger info, payload format: a plain 32-bit timestamp
  return ok;
}

Slave::Result Slave::get_daq_processor_info(PacketReader&, PacketWriter& response) {
  const auto max_lists = static_cast<std::uint16_t>(configuration_.daq.lists.size());
  const auto events = static_cast<std::uint16_t>(configuration_.events.size());
  // MIN_DAQ 0 (no predefined lists); DAQ_KEY_BYTE: the identification field type, a free address extension in every
  // entry, no optimisation.
  const auto key_byte = static_cast<std::uint8_t>(static_cast<std::uint8_t>(configuration_.identification_field) << 6U);
  response.u8(daq_properties).u16(max_lists).u16(events).u8(0).u8(key_byte);
  return ok;
}

// NOLINTNEXTLINE(readability-make-member-function-const): every handler has the table's signature
Slave::Result Slave::get_daq_resolution_info(PacketReader&, PacketWriter& response) {
  const auto timestamp_mode = static_cast<std::uint8_t>(static_cast<std::uint8_t>(configuration_.timestamp_size) |
                                                        (configuration_.timestamp_unit << 4U));
  response.u8(1).u8(max_entry_size()).u8(1).u8(0).u8(timestamp_mode).u16(configuration_.timestamp_ticks);
  return ok;
}

// The event's name is uploaded through the MTA afterwards, as for GET_ID.
Slave::Result Slave::get_daq_event_info(PacketReader& request, PacketWriter& response) {
  request.skip(1);
  const std::uint16_t event = request.u16();
  if (event >= configuration_.events.size()) return fail(Error::out_of_range);
  const EventChannel& channel = configuration_.events[event];
  mta_ = {.identification = {reinterpret_cast<const std::uint8_t*>(channel.name.data()), channel.name.size()},
          .points_to_identification = true};
  response.u8(event_properties).u8(0xFF).u8(static_cast<std::uint8_t>(channel.name.size()));
  response.u8(channel.time_cycle).u8(channel.time_unit).u8(channel.priority);
  return ok;
}

Slave::Result Slave::get_daq_list_info(PacketReader& request, PacketWriter& response) {
  request.skip(1);
  const std::uint16_t list = request.u16();
  if (list >= daq_lists_) return fail(Error::out_of_range);
  const DaqList& daq_list = configuration_.daq.lists[list];
  std::uint8_t most_entries = 0;
  for (std::size_t odt = 0; odt < daq_list.odt_count; ++odt) {
    const std::uint8_t count = configuration_.daq.odts[daq_list.first_odt + odt].entry_count;
    if (count > most_entries) most_entries = count;
  }
  response.u8(list_properties_daq).u8(daq_list.odt_count).u8(most_entries).u16(0);
  return ok;
}

// Two copies of the sampling loop, chosen at CONNECT: the usual layout's on its own keeps every register it had
// before the layouts were configurable (260 instructions per event for 16 four-byte entries on the Cortex-M4). A
// slave without a transmit queue samples nothing.
void Slave::on_event(std::uint16_t event) { sample_.load(std::memory_order_relaxed)(*this, event); }

void Slave::sample_nothing(Slave&, std::uint16_t) {}

void Slave::sample_in_usual_layout(Slave& slave, std::uint16_t event) {
  slave.sample_event(event, [](const SlaveConfiguration&, const DaqList& list, std::size_t, std::uint32_t now) {
    return AbsoluteIntelHeader{list, now};
  });
}

void Slave::sample_in_other_layout(Slave& slave, std::uint16_t event) {
  slave.sample_event(
      event, [](const SlaveConfiguration& configuration, const DaqList& list, std::size_t index, std::uint32_t now) {
        return EncodedHeader{configuration, static_cast<std::uint16_t>(index), list.first_odt, now};
      });
}

template <typename MakeHeader>
void Slave::sample_event(std::uint16_t event, MakeHeader make_header) {
  const DaqStorage& daq = configuration_.daq;
  const std::size_t headroom = static_cast<std::size_t>(configuration_.max_cto) + TransmitQueue::record_header;
  for (std::size_t index = 0; index < daq_lists_; ++index) {
    DaqList& list = daq.lists[index];
    if (list.event != event || !load_acquire(list.running)) continue;
    if (list.prescaler != 1) {  // most lists sample every event: they count nothing
      if (++list.prescaler_count < list.prescaler) continue;
      list.prescaler_count = 0;
    }

    // In this order (the timestamp last, as close to the copy as it can be) the compiler keeps everything in
    // registers across the clock's call.
    const bool announce_overload = overload_pending_.load(std::memory_order_relaxed);
    const Odt* const first = &daq.odts[list.first_odt];
    const std::size_t record_bytes =  // the list's records, summed when it started, and EV_DAQ_OVERLOAD's if due
        list.sample_bytes + (announce_overload ? TransmitQueue::record_header + overload_packet : 0);
    const bool stamped = (list.mode & daq_mode::timestamp) != 0;
    const std::uint32_t now = stamped && configuration_.timestamp != nullptr ? configuration_.timestamp() : 0;
    if (queue_sample(*configuration_.queue, daq, list, first, record_bytes, stamped,
                     make_header(configuration_, list, index, now), announce_overload, headroom)) {
      if (announce_overload) overload_pending_.store(false, std::memory_order_relaxed);
    } else {
      overloads_.fetch_add(1, std::memory_order_relaxed);
      overload_pending_.store(true, std::memory_order_relaxed);
    }
  }
}

}  // namespace duet::xcp
