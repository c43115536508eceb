#include <algorithm>
#include <cstdio>
#include <sstream>

#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

std::string hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%X", value);
  return text;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

std::string quoted(std::string_view text) {
  std::string result = "\"";
  for (char character : text) {
    if (character == '"' || character == '\\') result += '\\';
    result += character;
  }
  return result + '"';
}

std::string_view unit_keyword(std::uint8_t unit) {
  constexpr std::string_view units[] = {"UNIT_1NS",   "UNIT_10NS", "UNIT_100NS", "UNIT_1US",   "UNIT_10US",
                                        "UNIT_100US", "UNIT_1MS",  "UNIT_10MS",  "UNIT_100MS", "UNIT_1S"};
  return unit < std::size(units) ? units[unit] : "UNIT_1US";
}

std::string_view timestamp_size_keyword(std::uint8_t bytes) {
  switch (bytes) {
    case 1: return "SIZE_BYTE";
    case 2: return "SIZE_WORD";
    default: return "SIZE_DWORD";
  }
}

std::string_view identification_keyword(IdentificationField field) {
  switch (field) {
    case IdentificationField::absolute: return "IDENTIFICATION_FIELD_TYPE_ABSOLUTE";
    case IdentificationField::relative_byte: return "IDENTIFICATION_FIELD_TYPE_RELATIVE_BYTE";
    case IdentificationField::relative_word: return "IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD";
    case IdentificationField::relative_word_aligned: return "IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD_ALIGNED";
  }
  return "IDENTIFICATION_FIELD_TYPE_ABSOLUTE";
}

std::string_view checksum_keyword(ChecksumType type) {
  switch (type) {
    case ChecksumType::add_11: return "XCP_ADD_11";
    case ChecksumType::add_12: return "XCP_ADD_12";
    case ChecksumType::add_14: return "XCP_ADD_14";
    case ChecksumType::add_22: return "XCP_ADD_22";
    case ChecksumType::add_24: return "XCP_ADD_24";
    case ChecksumType::add_44: return "XCP_ADD_44";
    case ChecksumType::crc_16: return "XCP_CRC_16";
    case ChecksumType::crc_16_ccitt: return "XCP_CRC_16_CITT";  // the AML's spelling
    case ChecksumType::crc_32: return "XCP_CRC_32";
  }
  return "XCP_CRC_16_CITT";
}

// One COMPU_METHOD per distinct conversion and unit, named after them.
std::string conversion_name(const Variable& variable) {
  if (!variable.labels.empty()) return "duet_verbal_" + variable.name;
  if (variable.conversion == Conversion{}) return "duet_identity";
  return "duet_linear_" + variable.name;
}

void write_variable_common(std::ostringstream& out, const Variable& variable) {
  out << "      ECU_ADDRESS_EXTENSION " << static_cast<unsigned>(variable.extension) << "\n";
  if (!variable.unit.empty()) out << "      PHYS_UNIT " << quoted(variable.unit) << "\n";
  if (!variable.dimensions.empty()) {
    out << "      MATRIX_DIM";
    for (std::uint32_t dimension : variable.dimensions) out << " " << dimension;
    out << "\n";
  } else if (variable.count > 1) {
    out << "      MATRIX_DIM " << variable.count << "\n";
  }
}

// A TAB_VERB conversion and its table: the raw values a master shows by name.
void write_verbal_conversion(std::ostringstream& out, const Variable& variable) {
  const std::string name = conversion_name(variable);
  out << "    /begin COMPU_METHOD " << name << R"( "" TAB_VERB "%12.0" "" COMPU_TAB_REF )" << name
      << "_table /end COMPU_METHOD\n";
  out << "    /begin COMPU_VTAB " << name << "_table \"\" TAB_VERB " << variable.labels.size();
  for (const Label& label : variable.labels) out << " " << number(label.raw) << " " << quoted(label.text);
  out << " /end COMPU_VTAB\n";
}

bool covers(const MemoryInfo& memory, std::uint32_t address, std::size_t size) {
  return address >= memory.address && std::uint64_t{address} + size <= std::uint64_t{memory.address} + memory.size;
}

// PrgType and MemoryType of a segment. The calibration segment's address is its working page, which is RAM (the
// reference page's copy is the firmware's business): DATA, the program data a master calibrates online, in RAM.
// Signals and the executive's account are VARIABLES in RAM.
void write_memory_segment(std::ostringstream& out, const MemoryInfo& memory, std::size_t segment_number,
                          const A2lDescription& a2l) {
  out << "      /begin MEMORY_SEGMENT " << memory.name << " \"\" " << (memory.calibration ? "DATA" : "VARIABLES")
      << " RAM INTERN " << hex(memory.address) << " " << hex(memory.size) << " -1 -1 -1 -1 -1\n";
  if (memory.calibration) {
    const bool reference = a2l.calibration_reference_page;
    out << "        /begin IF_DATA XCP\n";
    out << "          /begin SEGMENT " << segment_number << " " << (reference ? 2 : 1) << " "
        << static_cast<unsigned>(memory.extension) << " 0 0\n";
    out << "            /begin CHECKSUM " << checksum_keyword(a2l.checksum_type) << " MAX_BLOCK_SIZE "
        << hex(a2l.checksum_max_block_size) << R"( EXTERNAL_FUNCTION "" /end CHECKSUM)" << '\n';
    out << "            /begin PAGE 0 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_DONT_CARE"
           " /end PAGE\n";
    if (reference) {
      out << "            /begin PAGE 1 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_NOT_ALLOWED"
             " /end PAGE\n";
    }
    out << "          /end SEGMENT\n";
    out << "        /end IF_DATA\n";
  }
  out << "      /end MEMORY_SEGMENT\n";
}

// The EPK's own segment, when no declared one holds it: constant bytes of the program image, neither calibration
// data (DATA) nor variables, that a master only reads (ROM), wherever the chip keeps them.
void write_epk(std::ostringstream& out, const A2lDescription& a2l) {
  if (a2l.epk.empty()) return;
  out << "      EPK " << quoted(a2l.epk) << "\n";
  out << "      ADDR_EPK " << hex(a2l.epk_address) << "\n";
  const bool covered = std::any_of(a2l.memory.begin(), a2l.memory.end(), [&a2l](const MemoryInfo& memory) {
    return covers(memory, a2l.epk_address, a2l.epk.size());
  });
  if (!covered) {
    out << "      /begin MEMORY_SEGMENT epk \"the ECU program identifier\" CODE ROM INTERN " << hex(a2l.epk_address)
        << " " << hex(static_cast<std::uint32_t>(a2l.epk.size())) << " -1 -1 -1 -1 -1\n";
    out << "      /end MEMORY_SEGMENT\n";
  }
}

// The events' short names (XCP's EVENT allows 8 characters), unique: a given short name that fits is kept; else the
// name (or the given short name) is cut to 8 characters keeping a trailing number ("DMA2_Stream3" -> "DMA2_St3"), and
// numbered from 1 when that is taken.
std::vector<std::string> short_names(const std::vector<EventInfo>& events) {
  static constexpr std::size_t limit = 8;
  std::vector<std::string> names(events.size());
  auto taken = [&names](const std::string& name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  auto fit = [](const std::string& stem, const std::string& suffix) {
    return stem.substr(0, limit - std::min(limit, suffix.size())) + suffix.substr(0, limit);
  };
  for (std::size_t index = 0; index < events.size(); ++index) {
    const std::string& given = events[index].short_name;
    if (!given.empty() && given.size() <= limit && !taken(given)) names[index] = given;
  }
  for (std::size_t index = 0; index < events.size(); ++index) {
    if (!names[index].empty()) continue;
    const EventInfo& event = events[index];
    const std::string& base = event.short_name.empty() ? event.name : event.short_name;
    std::string name = base.substr(0, limit);
    if (base.size() > limit) {
      const std::size_t digits = base.find_last_not_of("0123456789") + 1;
      name = fit(base.substr(0, digits), base.substr(digits));
    }
    for (unsigned number = 1; name.empty() || taken(name); ++number) name = fit(base, std::to_string(number));
    names[index] = name;
  }
  return names;
}

}  // namespace

std::string write_a2l(const A2lDescription& a2l) {
  std::ostringstream out;
  out << "ASAP2_VERSION 1 71\n";
  out << "/begin PROJECT " << a2l.project << " " << quoted("written by duet") << "\n";
  out << "  /begin HEADER " << quoted(a2l.description) << "\n  /end HEADER\n";
  out << "  /begin MODULE " << a2l.module << " " << quoted(a2l.description) << "\n";

  out << "    /begin MOD_PAR \"\"\n";
  write_epk(out, a2l);
  std::size_t segment_number = 0;
  for (const MemoryInfo& memory : a2l.memory) {
    write_memory_segment(out, memory, segment_number, a2l);
    if (memory.calibration) ++segment_number;
  }
  out << "    /end MOD_PAR\n";
  out << "    /begin MOD_COMMON \"\"\n      BYTE_ORDER MSB_LAST\n      ALIGNMENT_BYTE 1\n"
         "      ALIGNMENT_WORD 1\n      ALIGNMENT_LONG 1\n      ALIGNMENT_FLOAT32_IEEE 1\n"
         "      ALIGNMENT_FLOAT64_IEEE 1\n    /end MOD_COMMON\n";

  // T1 (1 s) bounds a command's answer, T2 (2 s) the longer ones (BUILD_CHECKSUM); T3 to T7 are for programming and
  // resets, which the slave does not do.
  out << "    /begin IF_DATA XCP\n";
  out << "      /begin PROTOCOL_LAYER 0x0100 1000 2000 0 0 0 0 0 " << static_cast<unsigned>(a2l.max_cto) << " "
      << a2l.max_dto << " BYTE_ORDER_MSB_LAST ADDRESS_GRANULARITY_BYTE\n";
  // The commands the slave handles beyond the mandatory CONNECT, DISCONNECT, GET_STATUS and SYNCH.
  for (std::string_view command : {"GET_COMM_MODE_INFO",
                                   "GET_ID",
                                   "SET_MTA",
                                   "UPLOAD",
                                   "SHORT_UPLOAD",
                                   "BUILD_CHECKSUM",
                                   "GET_SEED",
                                   "UNLOCK",
                                   "DOWNLOAD",
                                   "DOWNLOAD_NEXT",
                                   "DOWNLOAD_MAX",
                                   "SHORT_DOWNLOAD",
                                   "MODIFY_BITS",
                                   "SET_CAL_PAGE",
                                   "GET_CAL_PAGE",
                                   "GET_PAG_PROCESSOR_INFO",
                                   "GET_SEGMENT_INFO",
                                   "GET_PAGE_INFO",
                                   "SET_SEGMENT_MODE",
                                   "GET_SEGMENT_MODE",
                                   "COPY_CAL_PAGE",
                                   "CLEAR_DAQ_LIST",
                                   "SET_DAQ_PTR",
                                   "WRITE_DAQ",
                                   "SET_DAQ_LIST_MODE",
                                   "GET_DAQ_LIST_MODE",
                                   "START_STOP_DAQ_LIST",
                                   "START_STOP_SYNCH",
                                   "GET_DAQ_CLOCK",
                                   "READ_DAQ",
                                   "GET_DAQ_PROCESSOR_INFO",
                                   "GET_DAQ_RESOLUTION_INFO",
                                   "GET_DAQ_LIST_INFO",
                                   "GET_DAQ_EVENT_INFO",
                                   "FREE_DAQ",
                                   "ALLOC_DAQ",
                                   "ALLOC_ODT",
                                   "ALLOC_ODT_ENTRY",
                                   "WRITE_DAQ_MULTIPLE"}) {
    out << "        OPTIONAL_CMD " << command << "\n";
  }
  if (a2l.user_command) out << "        OPTIONAL_CMD USER_CMD\n";
  // Master block mode (DOWNLOAD_NEXT) with up to 255 packets and no minimum separation; no slave block mode.
  out << "        COMMUNICATION_MODE_SUPPORTED BLOCK MASTER 255 0\n";
  out << "      /end PROTOCOL_LAYER\n";
  out << "      /begin DAQ DYNAMIC " << a2l.max_daq_lists << " " << a2l.events.size()
      << " 0 OPTIMISATION_TYPE_DEFAULT ADDRESS_EXTENSION_FREE " << identification_keyword(a2l.identification_field)
      << " GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE " << hex(a2l.max_odt_entry_size) << " OVERLOAD_INDICATION_EVENT\n";
  out << "        PRESCALER_SUPPORTED\n";
  if (a2l.timestamp_size != 0) {
    out << "        /begin TIMESTAMP_SUPPORTED " << a2l.timestamp_ticks << " "
        << timestamp_size_keyword(a2l.timestamp_size) << " " << unit_keyword(a2l.timestamp_unit)
        << " /end TIMESTAMP_SUPPORTED\n";
  }
  const std::vector<std::string> event_short_names = short_names(a2l.events);
  for (std::size_t index = 0; index < a2l.events.size(); ++index) {
    const EventInfo& event = a2l.events[index];
    // Name, short name, channel, direction, the most DAQ lists it takes (0xFF: any), cycle, unit, priority.
    out << "        /begin EVENT " << quoted(event.name) << " " << quoted(event_short_names[index]) << " "
        << event.channel << " DAQ 0xFF " << static_cast<unsigned>(event.time_cycle) << " "
        << static_cast<unsigned>(event.time_unit) << " " << static_cast<unsigned>(event.priority) << " /end EVENT\n";
  }
  out << "      /end DAQ\n";
  out << "      /begin PAG " << segment_number << " /end PAG\n";
  const bool tcp = a2l.transport.protocol == Protocol::tcp;
  out << "      /begin " << (tcp ? "XCP_ON_TCP_IP" : "XCP_ON_UDP_IP") << " 0x0100 " << a2l.transport.port << " ADDRESS "
      << quoted(a2l.transport.host) << " /end " << (tcp ? "XCP_ON_TCP_IP" : "XCP_ON_UDP_IP") << "\n";
  out << "    /end IF_DATA\n";

  // FORMAT is "%Length.Layout": 12 characters in all, 6 after the decimal point.
  out << "    /begin COMPU_METHOD duet_identity \"\" IDENTICAL \"%12.6\" \"\" /end COMPU_METHOD\n";
  for (const std::vector<Variable>* list : {&a2l.measurements, &a2l.characteristics}) {
    for (const Variable& variable : *list) {
      if (!variable.labels.empty()) {
        write_verbal_conversion(out, variable);
        continue;
      }
      if (variable.conversion == Conversion{}) continue;
      out << "    /begin COMPU_METHOD " << conversion_name(variable) << R"( "" LINEAR "%12.6" )"
          << quoted(variable.unit) << " COEFFS_LINEAR " << number(variable.conversion.factor) << " "
          << number(variable.conversion.offset) << " /end COMPU_METHOD\n";
    }
  }
  for (DataType type : {DataType::uint8, DataType::int8, DataType::uint16, DataType::int16, DataType::uint32,
                        DataType::int32, DataType::uint64, DataType::int64, DataType::float32, DataType::float64}) {
    out << "    /begin RECORD_LAYOUT duet_" << a2l_name(type) << " FNC_VALUES 1 " << a2l_name(type)
        << " ROW_DIR DIRECT /end RECORD_LAYOUT\n";
  }
  for (const Variable& variable : a2l.measurements) {
    out << "    /begin MEASUREMENT " << variable.name << " " << quoted(variable.description) << " "
        << a2l_name(variable.type) << " " << conversion_name(variable) << " 0 0 " << number(variable.minimum) << " "
        << number(variable.maximum) << "\n";
    out << "      ECU_ADDRESS " << hex(variable.address) << "\n";
    write_variable_common(out, variable);
    out << "    /end MEASUREMENT\n";
  }
  for (const Variable& variable : a2l.characteristics) {
    out << "    /begin CHARACTERISTIC " << variable.name << " " << quoted(variable.description) << " "
        << (variable.count > 1 ? "VAL_BLK " : "VALUE ") << hex(variable.address) << " duet_" << a2l_name(variable.type)
        << " 0 " << conversion_name(variable) << " " << number(variable.minimum) << " " << number(variable.maximum)
        << "\n";
    write_variable_common(out, variable);
    out << "    /end CHARACTERISTIC\n";
  }
  out << "  /end MODULE\n";
  out << "/end PROJECT\n";
  return out.str();
}

}  // namespace duet::xcp::host
