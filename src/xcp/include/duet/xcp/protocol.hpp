#pragma once
// XCP (ASAM MCD-1 XCP 1.x) on the wire: packet identifiers, command codes, error and event codes, resource bits.
// Numbers from the XCP standard's protocol layer; shared by the slave and the master.

#include <cstdint>

namespace duet::xcp {

// The first byte of every packet from the slave.
namespace pid {
inline constexpr std::uint8_t response = 0xFF;
inline constexpr std::uint8_t error = 0xFE;
inline constexpr std::uint8_t event = 0xFD;
inline constexpr std::uint8_t service = 0xFC;
// Below 0xFC: DAQ data, the ODT identification.
}  // namespace pid

enum class Command : std::uint8_t {
  connect = 0xFF,
  disconnect = 0xFE,
  get_status = 0xFD,
  synch = 0xFC,
  get_comm_mode_info = 0xFB,
  get_id = 0xFA,
  set_request = 0xF9,
  get_seed = 0xF8,
  unlock = 0xF7,
  set_mta = 0xF6,
  upload = 0xF5,
  short_upload = 0xF4,
  build_checksum = 0xF3,
  transport_layer_cmd = 0xF2,
  user_cmd = 0xF1,
  download = 0xF0,
  download_next = 0xEF,
  download_max = 0xEE,
  short_download = 0xED,
  modify_bits = 0xEC,
  set_cal_page = 0xEB,
  get_cal_page = 0xEA,
  get_pag_processor_info = 0xE9,
  get_segment_info = 0xE8,
  get_page_info = 0xE7,
  set_segment_mode = 0xE6,
  get_segment_mode = 0xE5,
  copy_cal_page = 0xE4,
  clear_daq_list = 0xE3,
  set_daq_ptr = 0xE2,
  write_daq = 0xE1,
  set_daq_list_mode = 0xE0,
  get_daq_list_mode = 0xDF,
  start_stop_daq_list = 0xDE,
  start_stop_synch = 0xDD,
  get_daq_clock = 0xDC,
  read_daq = 0xDB,
  get_daq_processor_info = 0xDA,
  get_daq_resolution_info = 0xD9,
  get_daq_list_info = 0xD8,
  get_daq_event_info = 0xD7,
  free_daq = 0xD6,
  alloc_daq = 0xD5,
  alloc_odt = 0xD4,
  alloc_odt_entry = 0xD3,
  write_daq_multiple = 0xC7,
  level_1 = 0xC0,
};

enum class Error : std::uint8_t {
  cmd_synch = 0x00,
  cmd_busy = 0x10,
  daq_active = 0x11,
  pgm_active = 0x12,
  cmd_unknown = 0x20,
  cmd_syntax = 0x21,
  out_of_range = 0x22,
  write_protected = 0x23,
  access_denied = 0x24,
  access_locked = 0x25,
  page_not_valid = 0x26,
  mode_not_valid = 0x27,
  segment_not_valid = 0x28,
  sequence = 0x29,
  daq_config = 0x2A,
  memory_overflow = 0x30,
  generic = 0x31,
  verify = 0x32,
  resource_temporary_not_accessible = 0x33,
  subcmd_unknown = 0x34,
  timecorr_state_change = 0x35,
};

// The error code's name as the standard spells it ("ERR_ACCESS_DENIED"), for messages.
constexpr const char* name(Error error) {
  switch (error) {
    case Error::cmd_synch: return "ERR_CMD_SYNCH";
    case Error::cmd_busy: return "ERR_CMD_BUSY";
    case Error::daq_active: return "ERR_DAQ_ACTIVE";
    case Error::pgm_active: return "ERR_PGM_ACTIVE";
    case Error::cmd_unknown: return "ERR_CMD_UNKNOWN";
    case Error::cmd_syntax: return "ERR_CMD_SYNTAX";
    case Error::out_of_range: return "ERR_OUT_OF_RANGE";
    case Error::write_protected: return "ERR_WRITE_PROTECTED";
    case Error::access_denied: return "ERR_ACCESS_DENIED";
    case Error::access_locked: return "ERR_ACCESS_LOCKED";
    case Error::page_not_valid: return "ERR_PAGE_NOT_VALID";
    case Error::mode_not_valid: return "ERR_MODE_NOT_VALID";
    case Error::segment_not_valid: return "ERR_SEGMENT_NOT_VALID";
    case Error::sequence: return "ERR_SEQUENCE";
    case Error::daq_config: return "ERR_DAQ_CONFIG";
    case Error::memory_overflow: return "ERR_MEMORY_OVERFLOW";
    case Error::generic: return "ERR_GENERIC";
    case Error::verify: return "ERR_VERIFY";
    case Error::resource_temporary_not_accessible: return "ERR_RESOURCE_TEMPORARY_NOT_ACCESSIBLE";
    case Error::subcmd_unknown: return "ERR_SUBCMD_UNKNOWN";
    case Error::timecorr_state_change: return "ERR_TIMECORR_STATE_CHANGE";
  }
  return "ERR_UNKNOWN_CODE";
}

enum class EventCode : std::uint8_t {
  resume_mode = 0x00,
  clear_daq = 0x01,
  store_daq = 0x02,
  store_cal = 0x03,
  cmd_pending = 0x05,
  daq_overload = 0x06,
  session_terminated = 0x07,
  time_sync = 0x08,
  stim_timeout = 0x09,
  sleep = 0x0A,
  wake_up = 0x0B,
  ecu_state = 0x0C,
  user = 0xFE,
  transport = 0xFF,
};

// CONNECT's RESOURCE byte, and the resource protection status of GET_STATUS, GET_SEED and UNLOCK.
namespace resource {
inline constexpr std::uint8_t calibration_paging = 0x01;
inline constexpr std::uint8_t daq = 0x04;
inline constexpr std::uint8_t stim = 0x08;
inline constexpr std::uint8_t programming = 0x10;
inline constexpr std::uint8_t debugging = 0x20;
}  // namespace resource

inline constexpr std::uint8_t protocol_layer_version = 0x01;
inline constexpr std::uint8_t transport_layer_version = 0x01;

}  // namespace duet::xcp
