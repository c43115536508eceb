// The checker's keyword table, written as the standards write it: each block's fixed values as "Label:type" and its
// optional keywords as "KEYWORD Label:type ...", separated by ';' (a leading '*' lets one repeat). Types: ident, string
// (string<N>: at most N characters), float, int, uint, long, ulong (ASAP2's 2- and 4-byte integers), uchar (AML), and
// {set} for one keyword of a set below. "type+" repeats a value at least once, "type*" any number of times, and
// "a,b*" repeats a group.

#include "a2l_rules.hpp"

#include <sstream>

namespace duet::xcp::host::a2l_rules {
namespace {

const std::map<std::string, std::vector<std::string>, std::less<>>& keyword_sets() {
  static const std::map<std::string, std::vector<std::string>, std::less<>> sets{
      {"datatype",
       {"UBYTE", "SBYTE", "UWORD", "SWORD", "ULONG", "SLONG", "A_UINT64", "A_INT64", "FLOAT16_IEEE", "FLOAT32_IEEE",
        "FLOAT64_IEEE"}},
      {"prg_type",
       {"CALIBRATION_VARIABLES", "CODE", "DATA", "EXCLUDE_FROM_FLASH", "OFFLINE_DATA", "RESERVED", "SERAM",
        "VARIABLES"}},
      {"memory_type", {"EEPROM", "EPROM", "FLASH", "RAM", "ROM", "REGISTER", "NOT_IN_ECU"}},
      {"attribute", {"INTERN", "EXTERN"}},
      {"conversion_type", {"IDENTICAL", "FORM", "LINEAR", "RAT_FUNC", "TAB_INTP", "TAB_NOINTP", "TAB_VERB"}},
      {"table_type", {"TAB_INTP", "TAB_NOINTP"}},
      {"verbal_table_type", {"TAB_VERB"}},
      {"byte_order",
       {"LITTLE_ENDIAN", "BIG_ENDIAN", "MSB_LAST", "MSB_FIRST", "MSB_FIRST_MSW_LAST", "MSB_LAST_MSW_FIRST"}},
      {"characteristic_type", {"ASCII", "CURVE", "MAP", "CUBOID", "CUBE_4", "CUBE_5", "VAL_BLK", "VALUE"}},
      {"axis_type", {"CURVE_AXIS", "COM_AXIS", "FIX_AXIS", "RES_AXIS", "STD_AXIS"}},
      {"index_mode", {"ALTERNATE_CURVES", "ALTERNATE_WITH_X", "ALTERNATE_WITH_Y", "COLUMN_DIR", "ROW_DIR"}},
      {"addressing", {"PBYTE", "PWORD", "PLONG", "PLONGLONG", "DIRECT"}},
      {"index_order", {"INDEX_INCR", "INDEX_DECR"}},
      {"data_size", {"BYTE", "WORD", "LONG"}},
      {"deposit", {"ABSOLUTE", "DIFFERENCE"}},
      {"monotony",
       {"MON_DECREASE", "MON_INCREASE", "STRICT_DECREASE", "STRICT_INCREASE", "MONOTONOUS", "STRICT_MON", "NOT_MON"}},
      {"calibration_access", {"CALIBRATION", "NO_CALIBRATION", "NOT_IN_MCD_SYSTEM", "OFFLINE_CALIBRATION"}},
      {"unit_type", {"DERIVED", "EXTENDED_SI"}},
      {"layout", {"ROW_DIR", "COLUMN_DIR"}},
      {"xcp_byte_order", {"BYTE_ORDER_MSB_LAST", "BYTE_ORDER_MSB_FIRST"}},
      {"xcp_granularity", {"ADDRESS_GRANULARITY_BYTE", "ADDRESS_GRANULARITY_WORD", "ADDRESS_GRANULARITY_DWORD"}},
      {"daq_config", {"STATIC", "DYNAMIC"}},
      {"optimisation",
       {"OPTIMISATION_TYPE_DEFAULT", "OPTIMISATION_TYPE_ODT_TYPE_16", "OPTIMISATION_TYPE_ODT_TYPE_32",
        "OPTIMISATION_TYPE_ODT_TYPE_64", "OPTIMISATION_TYPE_ODT_TYPE_ALIGNMENT", "OPTIMISATION_TYPE_MAX_ENTRY_SIZE"}},
      {"address_extension", {"ADDRESS_EXTENSION_FREE", "ADDRESS_EXTENSION_ODT", "ADDRESS_EXTENSION_DAQ"}},
      {"identification",
       {"IDENTIFICATION_FIELD_TYPE_ABSOLUTE", "IDENTIFICATION_FIELD_TYPE_RELATIVE_BYTE",
        "IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD", "IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD_ALIGNED"}},
      {"entry_granularity",
       {"GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE", "GRANULARITY_ODT_ENTRY_SIZE_DAQ_WORD",
        "GRANULARITY_ODT_ENTRY_SIZE_DAQ_DWORD", "GRANULARITY_ODT_ENTRY_SIZE_DAQ_DLONG"}},
      {"overload", {"OVERLOAD_INDICATION_NO_INDICATION", "OVERLOAD_INDICATION_PID", "OVERLOAD_INDICATION_EVENT"}},
      {"timestamp_size", {"NO_TIME_STAMP", "SIZE_BYTE", "SIZE_WORD", "SIZE_DWORD"}},
      {"timestamp_unit",
       {"UNIT_1NS", "UNIT_10NS", "UNIT_100NS", "UNIT_1US", "UNIT_10US", "UNIT_100US", "UNIT_1MS", "UNIT_10MS",
        "UNIT_100MS", "UNIT_1S", "UNIT_1PS", "UNIT_10PS", "UNIT_100PS"}},
      {"event_direction", {"DAQ", "STIM", "DAQ_STIM"}},
      {"checksum",
       {"XCP_ADD_11", "XCP_ADD_12", "XCP_ADD_14", "XCP_ADD_22", "XCP_ADD_24", "XCP_ADD_44", "XCP_CRC_16",
        "XCP_CRC_16_CITT", "XCP_CRC_32", "XCP_USER_DEFINED"}},
      {"ecu_access",
       {"ECU_ACCESS_NOT_ALLOWED", "ECU_ACCESS_WITHOUT_XCP_ONLY", "ECU_ACCESS_WITH_XCP_ONLY", "ECU_ACCESS_DONT_CARE"}},
      {"xcp_read_access",
       {"XCP_READ_ACCESS_NOT_ALLOWED", "XCP_READ_ACCESS_WITHOUT_ECU_ONLY", "XCP_READ_ACCESS_WITH_ECU_ONLY",
        "XCP_READ_ACCESS_DONT_CARE"}},
      {"xcp_write_access",
       {"XCP_WRITE_ACCESS_NOT_ALLOWED", "XCP_WRITE_ACCESS_WITHOUT_ECU_ONLY", "XCP_WRITE_ACCESS_WITH_ECU_ONLY",
        "XCP_WRITE_ACCESS_DONT_CARE"}},
      {"command",
       {"GET_COMM_MODE_INFO",
        "GET_ID",
        "SET_REQUEST",
        "GET_SEED",
        "UNLOCK",
        "SET_MTA",
        "UPLOAD",
        "SHORT_UPLOAD",
        "BUILD_CHECKSUM",
        "TRANSPORT_LAYER_CMD",
        "USER_CMD",
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
        "PROGRAM_START",
        "PROGRAM_CLEAR",
        "PROGRAM",
        "PROGRAM_RESET",
        "GET_PGM_PROCESSOR_INFO",
        "GET_SECTOR_INFO",
        "PROGRAM_PREPARE",
        "PROGRAM_FORMAT",
        "PROGRAM_NEXT",
        "PROGRAM_MAX",
        "PROGRAM_VERIFY",
        "WRITE_DAQ_MULTIPLE",
        "TIME_CORRELATION_PROPERTIES",
        "DTO_CTR_PROPERTIES",
        "GET_VERSION",
        "SET_DAQ_PACKED_MODE",
        "GET_DAQ_PACKED_MODE"}},
  };
  return sets;
}

struct Spec {
  std::string_view keyword;
  std::string_view parents;
  std::string_view fields;
  std::string_view items;
  bool once = false;
  bool unchecked = false;
};

// Optional keywords several blocks share.
#define DUET_A2L_VARIABLE_ITEMS                                                                                        \
  "ECU_ADDRESS_EXTENSION Extension:int; MATRIX_DIM Dimension:uint+; ARRAY_SIZE Number:uint; FORMAT Format:string; "    \
  "PHYS_UNIT Unit:string; BIT_MASK Mask:ulong; BYTE_ORDER Order:{byte_order}; DISPLAY_IDENTIFIER Name:ident; "         \
  "REF_MEMORY_SEGMENT Segment:ident; SYMBOL_LINK Symbol,Offset:string,long; MAX_REFRESH ScalingUnit,Rate:uint,ulong; " \
  "ADDRESS_TYPE Addressing:{addressing}; LAYOUT Layout:{layout}; MODEL_LINK Model:string; DISCRETE; "                  \
  "ENCODING Encoding:ident; "
#define DUET_A2L_CHARACTERISTIC_ITEMS                                                                           \
  DUET_A2L_VARIABLE_ITEMS                                                                                       \
  "NUMBER Number:uint; EXTENDED_LIMITS Lower,Upper:float,float; READ_ONLY; GUARD_RAILS; STEP_SIZE Step:float; " \
  "COMPARISON_QUANTITY Name:ident; CALIBRATION_ACCESS Access:{calibration_access}"
#define DUET_A2L_AXIS_ITEMS                                                                                    \
  "ECU_ADDRESS_EXTENSION Extension:int; FORMAT Format:string; PHYS_UNIT Unit:string; DEPOSIT Mode:{deposit}; " \
  "BYTE_ORDER Order:{byte_order}; EXTENDED_LIMITS Lower,Upper:float,float; READ_ONLY; GUARD_RAILS; "           \
  "MONOTONY Monotony:{monotony}; STEP_SIZE Step:float; DISPLAY_IDENTIFIER Name:ident; REF_MEMORY_SEGMENT "     \
  "Segment:ident; "                                                                                            \
  "SYMBOL_LINK Symbol,Offset:string,long; CALIBRATION_ACCESS Access:{calibration_access}; MAX_REFRESH "        \
  "ScalingUnit,Rate:uint,ulong; MODEL_LINK Model:string"
#define DUET_A2L_LAYOUT_AXIS(AXIS)                                                                                 \
  "AXIS_PTS_" AXIS " Position,Type,Order,Addressing:uint,{datatype},{index_order},{addressing}; NO_AXIS_PTS_" AXIS \
  " Position,Type:uint,{datatype}; FIX_NO_AXIS_PTS_" AXIS " Points:uint; SRC_ADDR_" AXIS                           \
  " Position,Type:uint,{datatype}; RIP_ADDR_" AXIS " Position,Type:uint,{datatype}; SHIFT_OP_" AXIS                \
  " Position,Type:uint,{datatype}; OFFSET_" AXIS " Position,Type:uint,{datatype}; DIST_OP_" AXIS                   \
  " Position,Type:uint,{datatype}; AXIS_RESCALE_" AXIS                                                             \
  " Position,Type,MaxPairs,Order,Addressing:uint,{datatype},uint,{index_order},{addressing}; "
#define DUET_A2L_ALIGNMENTS                                                                                       \
  "ALIGNMENT_BYTE Bytes:uint; ALIGNMENT_WORD Bytes:uint; ALIGNMENT_LONG Bytes:uint; ALIGNMENT_INT64 Bytes:uint; " \
  "ALIGNMENT_FLOAT16_IEEE Bytes:uint; ALIGNMENT_FLOAT32_IEEE Bytes:uint; ALIGNMENT_FLOAT64_IEEE Bytes:uint"
#define DUET_A2L_XCP_PARENTS \
  "IF_DATA XCP|IF_DATA XCPplus|XCP_ON_TCP_IP|XCP_ON_UDP_IP|XCP_ON_CAN|XCP_ON_SxI|XCP_ON_USB|XCP_ON_FLX"

const Spec specs[] = {
    {"PROJECT", "", "Name:ident LongIdentifier:string", "", true},
    {"HEADER", "PROJECT", "Comment:string", "VERSION Version:string; PROJECT_NO Number:ident", true},
    {"MODULE", "PROJECT", "Name:ident LongIdentifier:string", ""},
    {"A2ML", "MODULE", "", "", true, true},
    {"MOD_PAR", "MODULE", "Comment:string",
     "VERSION Version:string; *ADDR_EPK Address:ulong; EPK Identifier:string; SUPPLIER Name:string; CUSTOMER "
     "Name:string; CUSTOMER_NO Number:string; USER Name:string; PHONE_NO Number:string; ECU Name:string; CPU_TYPE "
     "Name:string; NO_OF_INTERFACES Number:uint; ECU_CALIBRATION_OFFSET Offset:long; *SYSTEM_CONSTANT "
     "Name,Value:string,string",
     true},
    {"MEMORY_SEGMENT", "MOD_PAR",
     "Name:ident LongIdentifier:string PrgType:{prg_type} MemoryType:{memory_type} Attribute:{attribute} "
     "Address:ulong Size:ulong Offset:long Offset:long Offset:long Offset:long Offset:long",
     ""},
    {"MEMORY_LAYOUT", "MOD_PAR",
     "PrgType:{prg_type} Address:ulong Size:ulong Offset:long Offset:long Offset:long Offset:long Offset:long", ""},
    {"CALIBRATION_METHOD", "MOD_PAR", "Method:string Version:ulong", ""},
    {"CALIBRATION_HANDLE", "CALIBRATION_METHOD", "Handle:long*", "CALIBRATION_HANDLE_TEXT Text:string"},
    {"MOD_COMMON", "MODULE", "Comment:string",
     "S_REC_LAYOUT Name:ident; DEPOSIT Mode:{deposit}; BYTE_ORDER Order:{byte_order}; DATA_SIZE "
     "Bits:uint; " DUET_A2L_ALIGNMENTS,
     true},
    {"COMPU_METHOD", "MODULE",
     "Name:ident LongIdentifier:string ConversionType:{conversion_type} Format:string Unit:string",
     "COEFFS a,b,c,d,e,f:float,float,float,float,float,float; COEFFS_LINEAR a,b:float,float; COMPU_TAB_REF "
     "Table:ident; REF_UNIT Unit:ident; STATUS_STRING_REF Table:ident"},
    {"FORMULA", "COMPU_METHOD", "Formula:string", "FORMULA_INV Formula:string", true},
    {"COMPU_TAB", "MODULE",
     "Name:ident LongIdentifier:string ConversionType:{table_type} NumberValuePairs:uint InVal,OutVal:float,float*",
     "DEFAULT_VALUE Text:string; DEFAULT_VALUE_NUMERIC Value:float"},
    {"COMPU_VTAB", "MODULE",
     "Name:ident LongIdentifier:string ConversionType:{verbal_table_type} NumberValuePairs:uint "
     "InVal,OutVal:float,string*",
     "DEFAULT_VALUE Text:string"},
    {"COMPU_VTAB_RANGE", "MODULE",
     "Name:ident LongIdentifier:string NumberValueTriples:uint InValMin,InValMax,OutVal:float,float,string*",
     "DEFAULT_VALUE Text:string"},
    {"UNIT", "MODULE", "Name:ident LongIdentifier:string Display:string Type:{unit_type}",
     "REF_UNIT Unit:ident; SI_EXPONENTS "
     "Length,Mass,Time,Current,Temperature,Amount,Luminous:int,int,int,int,int,int,int; "
     "UNIT_CONVERSION Gradient,Offset:float,float"},
    {"RECORD_LAYOUT", "MODULE", "Name:ident",
     "FNC_VALUES Position,Type,IndexMode,Addressing:uint,{datatype},{index_mode},{addressing}; "
     "IDENTIFICATION Position,Type:uint,{datatype}; *RESERVED Position,Size:uint,{data_size}; STATIC_RECORD_LAYOUT; "
     "STATIC_ADDRESS_OFFSETS; " DUET_A2L_LAYOUT_AXIS("X") DUET_A2L_LAYOUT_AXIS("Y") DUET_A2L_LAYOUT_AXIS("Z")
         DUET_A2L_LAYOUT_AXIS("4") DUET_A2L_LAYOUT_AXIS("5") DUET_A2L_ALIGNMENTS},
    {"MEASUREMENT", "MODULE",
     "Name:ident LongIdentifier:string Datatype:{datatype} Conversion:ident Resolution:uint Accuracy:float "
     "LowerLimit:float UpperLimit:float",
     DUET_A2L_VARIABLE_ITEMS "ECU_ADDRESS Address:ulong; ERROR_MASK Mask:ulong; READ_WRITE"},
    {"CHARACTERISTIC", "MODULE",
     "Name:ident LongIdentifier:string Type:{characteristic_type} Address:ulong Deposit:ident MaxDiff:float "
     "Conversion:ident LowerLimit:float UpperLimit:float",
     DUET_A2L_CHARACTERISTIC_ITEMS},
    {"AXIS_DESCR", "CHARACTERISTIC|TYPEDEF_CHARACTERISTIC",
     "Attribute:{axis_type} InputQuantity:ident Conversion:ident MaxAxisPoints:uint LowerLimit:float "
     "UpperLimit:float",
     "AXIS_PTS_REF Name:ident; CURVE_AXIS_REF Name:ident; FIX_AXIS_PAR Offset,Shift,Points:float,float,uint; "
     "FIX_AXIS_PAR_DIST Offset,Distance,Points:float,float,uint; DEPOSIT Mode:{deposit}; EXTENDED_LIMITS "
     "Lower,Upper:float,float; FORMAT Format:string; MAX_GRAD Gradient:float; MONOTONY Monotony:{monotony}; PHYS_UNIT "
     "Unit:string; READ_ONLY; STEP_SIZE Step:float; BYTE_ORDER Order:{byte_order}"},
    {"FIX_AXIS_PAR_LIST", "AXIS_DESCR", "AxisPoint:float+", "", true},
    {"AXIS_PTS", "MODULE",
     "Name:ident LongIdentifier:string Address:ulong InputQuantity:ident Deposit:ident MaxDiff:float "
     "Conversion:ident MaxAxisPoints:uint LowerLimit:float UpperLimit:float",
     DUET_A2L_AXIS_ITEMS},
    {"TYPEDEF_STRUCTURE", "MODULE", "Name:ident LongIdentifier:string Size:ulong",
     "ADDRESS_TYPE Addressing:{addressing}; CONSISTENT_EXCHANGE; SYMBOL_TYPE_LINK Symbol:string"},
    {"STRUCTURE_COMPONENT", "TYPEDEF_STRUCTURE", "Name:ident TypedefName:ident AddressOffset:ulong",
     "MATRIX_DIM Dimension:uint+; ADDRESS_TYPE Addressing:{addressing}; LAYOUT Layout:{layout}; SYMBOL_TYPE_LINK "
     "Symbol:string"},
    {"TYPEDEF_MEASUREMENT", "MODULE",
     "Name:ident LongIdentifier:string Datatype:{datatype} Conversion:ident Resolution:uint Accuracy:float "
     "LowerLimit:float UpperLimit:float",
     DUET_A2L_VARIABLE_ITEMS "ERROR_MASK Mask:ulong"},
    {"TYPEDEF_CHARACTERISTIC", "MODULE",
     "Name:ident LongIdentifier:string Type:{characteristic_type} Deposit:ident MaxDiff:float Conversion:ident "
     "LowerLimit:float UpperLimit:float",
     DUET_A2L_CHARACTERISTIC_ITEMS},
    {"TYPEDEF_AXIS", "MODULE",
     "Name:ident LongIdentifier:string InputQuantity:ident Deposit:ident MaxDiff:float Conversion:ident "
     "MaxAxisPoints:uint LowerLimit:float UpperLimit:float",
     DUET_A2L_AXIS_ITEMS},
    {"INSTANCE", "MODULE", "Name:ident LongIdentifier:string TypedefName:ident Address:ulong",
     "ECU_ADDRESS_EXTENSION Extension:int; MATRIX_DIM Dimension:uint+; READ_WRITE; LAYOUT Layout:{layout}; "
     "DISPLAY_IDENTIFIER Name:ident; ADDRESS_TYPE Addressing:{addressing}; SYMBOL_LINK Symbol,Offset:string,long; "
     "CALIBRATION_ACCESS Access:{calibration_access}; MAX_REFRESH ScalingUnit,Rate:uint,ulong; MODEL_LINK "
     "Model:string"},
    {"OVERWRITE", "INSTANCE", "Name:ident AxisNumber:ulong",
     "CONVERSION Name:ident; EXTENDED_LIMITS Lower,Upper:float,float; FORMAT Format:string; INPUT_QUANTITY "
     "Name:ident; LIMITS Lower,Upper:float,float; MONOTONY Monotony:{monotony}; PHYS_UNIT Unit:string"},
    {"GROUP", "MODULE", "Name:ident LongIdentifier:string", "ROOT"},
    {"FUNCTION", "MODULE", "Name:ident LongIdentifier:string", "FUNCTION_VERSION Version:string"},
    {"REF_CHARACTERISTIC", "GROUP|FUNCTION", "Name:ident*", "", true},
    {"REF_MEASUREMENT", "GROUP", "Name:ident*", "", true},
    {"SUB_GROUP", "GROUP", "Name:ident*", "", true},
    {"DEF_CHARACTERISTIC", "FUNCTION", "Name:ident*", "", true},
    {"IN_MEASUREMENT", "FUNCTION", "Name:ident*", "", true},
    {"OUT_MEASUREMENT", "FUNCTION", "Name:ident*", "", true},
    {"LOC_MEASUREMENT", "FUNCTION", "Name:ident*", "", true},
    {"SUB_FUNCTION", "FUNCTION", "Name:ident*", "", true},
    {"FUNCTION_LIST", "GROUP|MEASUREMENT|CHARACTERISTIC|AXIS_PTS", "Name:ident*", "", true},
    {"VIRTUAL", "MEASUREMENT", "MeasuringChannel:ident+", "", true},
    {"DEPENDENT_CHARACTERISTIC", "CHARACTERISTIC", "Formula:string Characteristic:ident*", "", true},
    {"VIRTUAL_CHARACTERISTIC", "CHARACTERISTIC", "Formula:string Characteristic:ident*", "", true},
    {"MAP_LIST", "CHARACTERISTIC", "Name:ident*", "", true},
    {"BIT_OPERATION", "MEASUREMENT", "", "LEFT_SHIFT Bits:ulong; RIGHT_SHIFT Bits:ulong; SIGN_EXTEND", true},
    {"ANNOTATION",
     "MEASUREMENT|CHARACTERISTIC|AXIS_PTS|AXIS_DESCR|GROUP|FUNCTION|TYPEDEF_MEASUREMENT|TYPEDEF_CHARACTERISTIC|"
     "TYPEDEF_AXIS|TYPEDEF_STRUCTURE|INSTANCE",
     "", "ANNOTATION_LABEL Label:string; ANNOTATION_ORIGIN Origin:string"},
    {"ANNOTATION_TEXT", "ANNOTATION", "Text:string*", "", true},
    {"IF_DATA", "MODULE|MEMORY_SEGMENT|MEASUREMENT|CHARACTERISTIC|AXIS_PTS|GROUP|FUNCTION|INSTANCE|MEMORY_LAYOUT",
     "Name:ident", ""},
    // The XCP IF_DATA, as XCP 1.x's AML declares it.
    {"PROTOCOL_LAYER", DUET_A2L_XCP_PARENTS,
     "Version:uint T1:uint T2:uint T3:uint T4:uint T5:uint T6:uint T7:uint MAX_CTO:uchar MAX_DTO:uint "
     "ByteOrder:{xcp_byte_order} AddressGranularity:{xcp_granularity}",
     "*OPTIONAL_CMD Command:{command}; COMMUNICATION_MODE_SUPPORTED; BLOCK; SLAVE; MASTER MAX_BS,MIN_ST:uchar,uchar; "
     "INTERLEAVED QUEUE_SIZE:uchar; SEED_AND_KEY_EXTERNAL_FUNCTION Name:string<255>; MAX_DTO_STIM Size:uint",
     true},
    {"DAQ", DUET_A2L_XCP_PARENTS,
     "Configuration:{daq_config} MAX_DAQ:uint MAX_EVENT_CHANNEL:uint MIN_DAQ:uchar Optimisation:{optimisation} "
     "AddressExtension:{address_extension} IdentificationField:{identification} "
     "Granularity:{entry_granularity} MAX_ODT_ENTRY_SIZE_DAQ:uchar OverloadIndication:{overload}",
     "PRESCALER_SUPPORTED; RESUME_SUPPORTED; PID_OFF_SUPPORTED; MAX_DAQ_TOTAL Lists:uint; MAX_ODT_TOTAL Odts:uint; "
     "MAX_ODT_DAQ_TOTAL Odts:uint; MAX_ODT_STIM_TOTAL Odts:uint; MAX_ODT_ENTRIES_TOTAL Entries:uint; "
     "MAX_ODT_ENTRIES_DAQ_TOTAL Entries:uint; MAX_ODT_ENTRIES_STIM_TOTAL Entries:uint; CPU_LOAD_MAX_TOTAL Load:float; "
     "CORE_LOAD_MAX_TOTAL Load:float",
     true},
    {"TIMESTAMP_SUPPORTED", "DAQ", "TIMESTAMP_TICKS:uint Size:{timestamp_size} Unit:{timestamp_unit}",
     "TIMESTAMP_FIXED", true},
    {"EVENT", "DAQ",
     "Name:string<100> ShortName:string<8> Channel:uint Direction:{event_direction} MAX_DAQ_LIST:uchar "
     "TIME_CYCLE:uchar TIME_UNIT:uchar PRIORITY:uchar",
     "CONSISTENCY Level:ident; MIN_CYCLE_TIME Cycle,Unit:uchar,uchar; CPU_LOAD_MAX Load:float"},
    {"DAQ_LIST", "DAQ", "Number:uint",
     "DAQ_LIST_TYPE Type:ident; MAX_ODT Odts:uchar; MAX_ODT_ENTRIES Entries:uchar; "
     "FIRST_PID Pid:uchar; EVENT_FIXED Event:uint"},
    {"STIM", "DAQ", "Granularity:{entry_granularity} MAX_ODT_ENTRY_SIZE_STIM:uchar", "BIT_STIM_SUPPORTED", true},
    {"PAG", DUET_A2L_XCP_PARENTS, "MAX_SEGMENTS:uchar", "FREEZE_SUPPORTED", true},
    {"PGM", DUET_A2L_XCP_PARENTS, "Mode:ident MAX_SECTORS:uchar MAX_CTO_PGM:uchar", "", true, true},
    {"SEGMENT", "IF_DATA XCP|IF_DATA XCPplus",
     "SegmentNumber:uchar NumberOfPages:uchar AddressExtension:uchar CompressionMethod:uchar "
     "EncryptionMethod:uchar",
     "PGM_VERIFY Value:ulong", true},
    {"CHECKSUM", "SEGMENT", "Type:{checksum}",
     "MAX_BLOCK_SIZE Size:ulong; EXTERNAL_FUNCTION Name:string<255>; MTA_BLOCK_SIZE_ALIGN Bytes:uint", true},
    {"PAGE", "SEGMENT",
     "PageNumber:uchar EcuAccess:{ecu_access} XcpReadAccess:{xcp_read_access} XcpWriteAccess:{xcp_write_access}",
     "INIT_SEGMENT Segment:uchar"},
    {"ADDRESS_MAPPING", "SEGMENT", "Source:ulong Destination:ulong Length:ulong", ""},
    {"XCP_ON_TCP_IP", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint Port:uint",
     "HOST_NAME Name:string<255>; ADDRESS Address:string<255>; IPV6 Address:string<255>"},
    {"XCP_ON_UDP_IP", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint Port:uint",
     "HOST_NAME Name:string<255>; ADDRESS Address:string<255>; IPV6 Address:string<255>"},
    {"XCP_ON_CAN", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint", "", false, true},
    {"XCP_ON_SxI", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint", "", false, true},
    {"XCP_ON_USB", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint", "", false, true},
    {"XCP_ON_FLX", "IF_DATA XCP|IF_DATA XCPplus", "Version:uint", "", false, true},
    {"DAQ_EVENT", "IF_DATA XCP|IF_DATA XCPplus", "", "", true, true},
};

Type parse_type(std::string_view text) {
  Type type;
  type.name = std::string{text};
  if (text == "ident") {
    type.kind = Type::Kind::identifier;
  } else if (text.starts_with("string")) {
    type.kind = Type::Kind::text;
    if (text.size() > 7) type.max_length = std::stoul(std::string{text.substr(7, text.size() - 8)});
    type.name = "string";
  } else if (text == "float") {
    type.kind = Type::Kind::number;
  } else if (text.starts_with("{")) {
    type.kind = Type::Kind::keyword;
    type.keywords = &keyword_sets().at(std::string{text.substr(1, text.size() - 2)});
  } else {
    static const std::map<std::string_view, std::pair<std::int64_t, std::int64_t>> ranges{
        {"uchar", {0, 0xFF}},
        {"int", {-32768, 32767}},
        {"uint", {0, 0xFFFF}},
        {"long", {-2147483648LL, 2147483647LL}},
        {"ulong", {0, 0xFFFFFFFFLL}}};
    const auto& [minimum, maximum] = ranges.at(text);
    type.kind = Type::Kind::whole;
    type.minimum = minimum;
    type.maximum = maximum;
  }
  return type;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  while (!text.empty()) {
    const std::size_t end = text.find(separator);
    std::string_view part = text.substr(0, end);
    while (part.starts_with(' ')) part.remove_prefix(1);
    while (part.ends_with(' ')) part.remove_suffix(1);
    if (!part.empty()) parts.push_back(part);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return parts;
}

std::vector<Field> parse_fields(const std::vector<std::string_view>& words) {
  std::vector<Field> fields;
  for (std::string_view word : words) {
    const std::size_t colon = word.find(':');
    Field field;
    field.label = std::string{word.substr(0, colon)};
    std::string_view types = word.substr(colon + 1);
    if (types.ends_with('*') || types.ends_with('+')) {
      field.repeated = true;
      field.at_least_one = types.back() == '+';
      types.remove_suffix(1);
    }
    for (std::string_view type : split(types, ',')) field.group.push_back(parse_type(type));
    fields.push_back(std::move(field));
  }
  return fields;
}

BlockRule parse(const Spec& spec) {
  BlockRule rule;
  rule.keyword = std::string{spec.keyword};
  for (std::string_view parent : split(spec.parents, '|')) rule.parents.emplace_back(parent);
  if (spec.parents.empty()) rule.parents.emplace_back();
  rule.fields = parse_fields(split(spec.fields, ' '));
  for (std::string_view text : split(spec.items, ';')) {
    std::vector<std::string_view> words = split(text, ' ');
    Item item;
    std::string_view keyword = words.front();
    item.repeatable = keyword.starts_with('*');
    if (item.repeatable) keyword.remove_prefix(1);
    item.keyword = std::string{keyword};
    item.fields = parse_fields({words.begin() + 1, words.end()});
    rule.items[item.keyword] = std::move(item);
  }
  rule.once = spec.once;
  rule.unchecked = spec.unchecked;
  return rule;
}

const std::multimap<std::string, BlockRule, std::less<>>& rules() {
  static const std::multimap<std::string, BlockRule, std::less<>> table = [] {
    std::multimap<std::string, BlockRule, std::less<>> parsed;
    for (const Spec& spec : specs) parsed.emplace(std::string{spec.keyword}, parse(spec));
    return parsed;
  }();
  return table;
}

}  // namespace

const BlockRule* rule_for(std::string_view keyword, std::string_view parent, bool& known) {
  const auto [first, last] = rules().equal_range(keyword);
  known = first != last;
  for (auto rule = first; rule != last; ++rule) {
    for (const std::string& allowed : rule->second.parents) {
      if (allowed == parent) return &rule->second;
    }
  }
  return nullptr;
}

const BlockRule& file_rule() {
  static const BlockRule rule =
      parse({"", "", "", "ASAP2_VERSION Major,Minor:uint,uint; A2ML_VERSION Major,Minor:uint,uint"});
  return rule;
}

}  // namespace duet::xcp::host::a2l_rules
