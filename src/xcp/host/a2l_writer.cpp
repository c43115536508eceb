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

// One COMPU_METHOD per distinct conversion and unit, named after them.
std::string conversion_name(const Variable& variable) {
  if (variable.conversion == Conversion{}) return "duet_identity";
  return "duet_linear_" + variable.name;
}

void write_variable_common(std::ostringstream& out, const Variable& variable) {
  out << "      ECU_ADDRESS_EXTENSION " << static_cast<unsigned>(variable.extension) << "\n";
  if (!variable.unit.empty()) out << "      PHYS_UNIT " << quoted(variable.unit) << "\n";
  if (variable.count > 1) out << "      MATRIX_DIM " << variable.count << "\n";
}

}  // namespace

std::string write_a2l(const A2lDescription& a2l) {
  std::ostringstream out;
  out << "ASAP2_VERSION 1 71\n";
  out << "/begin PROJECT " << a2l.project << " " << quoted("written by duet") << "\n";
  out << "  /begin HEADER " << quoted(a2l.description) << "\n  /end HEADER\n";
  out << "  /begin MODULE " << a2l.module << " " << quoted(a2l.description) << "\n";

  out << "    /begin MOD_PAR \"\"\n";
  std::size_t segment_number = 0;
  for (const MemoryInfo& memory : a2l.memory) {
    out << "      /begin MEMORY_SEGMENT " << memory.name << " \"\" DATA " << (memory.calibration ? "FLASH" : "RAM")
        << " INTERN " << hex(memory.address) << " " << hex(memory.size) << " -1 -1 -1 -1 -1\n";
    if (memory.calibration) {
      out << "        /begin IF_DATA XCP\n";
      out << "          /begin SEGMENT " << segment_number++ << " 2 " << static_cast<unsigned>(memory.extension)
          << " 0 0\n";
      out << R"(            /begin CHECKSUM XCP_CRC_16_CITT MAX_BLOCK_SIZE 0xFFFF EXTERNAL_FUNCTION "" /end CHECKSUM)"
          << '\n';
      out << "            /begin PAGE 0 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_DONT_CARE"
             " /end PAGE\n";
      out << "            /begin PAGE 1 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_NOT_ALLOWED"
             " /end PAGE\n";
      out << "          /end SEGMENT\n";
      out << "        /end IF_DATA\n";
    }
    out << "      /end MEMORY_SEGMENT\n";
  }
  out << "    /end MOD_PAR\n";
  out << "    /begin MOD_COMMON \"\"\n      BYTE_ORDER MSB_LAST\n      ALIGNMENT_BYTE 1\n"
         "      ALIGNMENT_WORD 1\n      ALIGNMENT_LONG 1\n      ALIGNMENT_FLOAT32_IEEE 1\n"
         "      ALIGNMENT_FLOAT64_IEEE 1\n    /end MOD_COMMON\n";

  out << "    /begin IF_DATA XCP\n";
  out << "      /begin PROTOCOL_LAYER 0x0100 1000 2000 0 0 0 0 0 " << static_cast<unsigned>(a2l.max_cto) << " "
      << a2l.max_dto << " BYTE_ORDER_MSB_LAST ADDRESS_GRANULARITY_BYTE\n";
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
                                   "WRITE_DAQ_MULTIPLE",
                                   "USER_CMD"}) {
    out << "        OPTIONAL_CMD " << command << "\n";
  }
  out << "        COMMUNICATION_MODE_SUPPORTED BLOCK MASTER 255 0\n";
  out << "      /end PROTOCOL_LAYER\n";
  out << "      /begin DAQ DYNAMIC " << a2l.max_daq_lists << " " << a2l.events.size()
      << " 0 OPTIMISATION_TYPE_DEFAULT ADDRESS_EXTENSION_FREE IDENTIFICATION_FIELD_TYPE_ABSOLUTE"
         " GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE 0xFF OVERLOAD_INDICATION_EVENT\n";
  out << "        PRESCALER_SUPPORTED\n";
  out << "        /begin TIMESTAMP_SUPPORTED " << a2l.timestamp_ticks << " SIZE_DWORD "
      << unit_keyword(a2l.timestamp_unit) << " /end TIMESTAMP_SUPPORTED\n";
  for (const EventInfo& event : a2l.events) {
    out << "        /begin EVENT " << quoted(event.name) << " " << quoted(event.name.substr(0, 8)) << " "
        << event.channel << " DAQ 0xFF " << static_cast<unsigned>(event.time_cycle) << " "
        << static_cast<unsigned>(event.time_unit) << " " << static_cast<unsigned>(event.priority) << " /end EVENT\n";
  }
  out << "      /end DAQ\n";
  out << "      /begin PAG " << segment_number << " /end PAG\n";
  const bool tcp = a2l.transport.protocol == Protocol::tcp;
  out << "      /begin " << (tcp ? "XCP_ON_TCP_IP" : "XCP_ON_UDP_IP") << " 0x0100 " << a2l.transport.port << " ADDRESS "
      << quoted(a2l.transport.host) << " /end " << (tcp ? "XCP_ON_TCP_IP" : "XCP_ON_UDP_IP") << "\n";
  out << "    /end IF_DATA\n";

  out << "    /begin COMPU_METHOD duet_identity \"\" IDENTICAL \"%.6\" \"\" /end COMPU_METHOD\n";
  for (const std::vector<Variable>* list : {&a2l.measurements, &a2l.characteristics}) {
    for (const Variable& variable : *list) {
      if (variable.conversion == Conversion{}) continue;
      out << "    /begin COMPU_METHOD " << conversion_name(variable) << R"( "" LINEAR "%.6" )" << quoted(variable.unit)
          << " COEFFS_LINEAR " << number(variable.conversion.factor) << " " << number(variable.conversion.offset)
          << " /end COMPU_METHOD\n";
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
