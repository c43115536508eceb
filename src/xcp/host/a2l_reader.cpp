// Reads A2L text into an A2lDescription: the syntax tree (a2l_syntax.hpp), then the parts a master needs. What it meets
// and cannot use (a conversion table, a bit mask, an array of structures, ...) becomes a warning, never silence.

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>
#include <optional>

#include "a2l_syntax.hpp"
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

using a2l_syntax::after;
using a2l_syntax::Block;
using a2l_syntax::child;
using a2l_syntax::Place;
using a2l_syntax::Token;

// Structures inside structures deeper than this are a loop.
constexpr std::size_t max_structure_depth = 16;

constexpr std::string_view time_units[] = {"UNIT_1NS",   "UNIT_10NS", "UNIT_100NS", "UNIT_1US",   "UNIT_10US",
                                           "UNIT_100US", "UNIT_1MS",  "UNIT_10MS",  "UNIT_100MS", "UNIT_1S"};

// A conversion the reader can apply (identical, linear, or a rational function that is linear).
struct CompuMethod {
  Conversion conversion;
  std::string unit;
  std::string verbal_table;  // TAB_VERB: the COMPU_VTAB that names the raw values
  std::string unapplied;     // the conversion type it cannot apply (Variable::unapplied_conversion)
};

// One item of a record layout: where it sits among the others (its position) and what it holds.
struct LayoutItem {
  std::string keyword;  // FNC_VALUES, AXIS_PTS_X, NO_AXIS_PTS_X, RESERVED, ...
  std::uint64_t position = 0;
  std::size_t element_size = 1;
  DataType type = DataType::uint8;
};

using Alignments = std::map<std::string, std::size_t, std::less<>>;  // ALIGNMENT_WORD -> 2, ...

struct RecordLayout {
  std::vector<LayoutItem> items;
  Alignments alignments;  // its own ALIGNMENT_*, before MOD_COMMON's
  bool direct = true;     // FNC_VALUES addressed DIRECT, not through a pointer
  const Block* block = nullptr;
};

std::string_view alignment_keyword(DataType type) {
  switch (type) {
    case DataType::uint8:
    case DataType::int8: return "ALIGNMENT_BYTE";
    case DataType::uint16:
    case DataType::int16: return "ALIGNMENT_WORD";
    case DataType::uint32:
    case DataType::int32: return "ALIGNMENT_LONG";
    case DataType::uint64:
    case DataType::int64: return "ALIGNMENT_INT64";
    case DataType::float32: return "ALIGNMENT_FLOAT32_IEEE";
    case DataType::float64: return "ALIGNMENT_FLOAT64_IEEE";
  }
  return "ALIGNMENT_BYTE";
}

// The ALIGNMENT_* keywords among a block's values.
Alignments alignments_in(const Block& block) {
  Alignments found;
  for (std::size_t index = 0; index + 1 < block.values.size(); ++index) {
    std::size_t bytes = 0;
    const std::string& number = block.values[index + 1].value;
    if (block.values[index].value.starts_with("ALIGNMENT_") &&
        std::from_chars(number.data(), number.data() + number.size(), bytes).ec == std::errc{} && bytes > 0) {
      found[block.values[index].value] = bytes;
    }
  }
  return found;
}

class Reader {
 public:
  explicit Reader(const a2l_syntax::Tree& tree) : tree_(tree) {}

  std::optional<std::string> error;
  A2lDescription a2l;

  void read_module(const Block& module) {
    if (const Token* name = value(module, 0, "the module's name")) a2l.module = name->value;
    if (module.values.size() > 1) a2l.description = module.values[1].value;
    for (const Block& block : module.children) {
      if (block.keyword == "UNIT" && block.values.size() >= 3) units_[block.values[0].value] = block.values[2].value;
    }
    if (const Block* common = child(module, "MOD_COMMON")) read_module_common(*common);
    for (const Block& block : module.children) index_definitions(block);
    if (const Block* parameters = child(module, "MOD_PAR")) read_module_parameters(*parameters);
    for (const Block& block : module.children) {
      if (block.keyword == "IF_DATA" && !block.values.empty() && block.values[0].value == "XCP") read_xcp(block);
    }
    for (const Block& block : module.children) {
      if (block.keyword == "AXIS_PTS") {
        if (auto axis = axis_points(block, std::nullopt)) a2l.characteristics.push_back(*axis);
      }
    }
    for (const Block& block : module.children) read_module_block(block);
  }

  void warn(const Place& place, const std::string& what) { a2l.warnings.push_back(tree_.where(place) + ": " + what); }

 private:
  void fail(const Place& place, const std::string& problem) {
    if (!error) error = tree_.where(place) + ": " + problem;
  }

  // The block's value at `index`, or an error naming the block and what was expected there.
  const Token* value(const Block& block, std::size_t index, std::string_view what) {
    if (index < block.values.size()) return &block.values[index];
    fail(block.place, block.keyword + ": " + std::string{what} + " is missing");
    return nullptr;
  }

  std::optional<double> real(const Token* token) {
    if (token == nullptr) return std::nullopt;
    if (const auto whole = parse_integer(token->value)) return static_cast<double>(*whole);  // 0x... too
    char* end = nullptr;
    const double parsed = std::strtod(token->value.c_str(), &end);
    if (end == token->value.c_str() || *end != '\0') {
      fail(token->place, "'" + token->value + "' is not a number");
      return std::nullopt;
    }
    return parsed;
  }

  static std::optional<std::uint64_t> parse_integer(std::string_view text) {
    int base = 10;
    if (text.starts_with("0x") || text.starts_with("0X")) {
      text.remove_prefix(2);
      base = 16;
    }
    std::uint64_t parsed = 0;
    const auto [end, problem] = std::from_chars(text.data(), text.data() + text.size(), parsed, base);
    if (text.empty() || problem != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return parsed;
  }

  std::optional<std::uint64_t> integer(const Token* token) {
    if (token == nullptr) return std::nullopt;
    const auto parsed = parse_integer(token->value);
    if (!parsed) fail(token->place, "'" + token->value + "' is not a whole number");
    return parsed;
  }

  std::optional<DataType> data_type(const Token* token) {
    if (token == nullptr) return std::nullopt;
    for (DataType type : {DataType::uint8, DataType::int8, DataType::uint16, DataType::int16, DataType::uint32,
                          DataType::int32, DataType::uint64, DataType::int64, DataType::float32, DataType::float64}) {
      if (token->value == a2l_name(type)) return type;
    }
    fail(token->place, "'" + token->value + "' is not an A2L data type");
    return std::nullopt;
  }

  // The numbers after `keyword` among a block's values (MATRIX_DIM 2 3), up to the next word that is not one.
  std::vector<std::uint64_t> numbers_after(const Block& block, std::string_view keyword) {
    std::vector<std::uint64_t> numbers;
    for (std::size_t index = 0; index < block.values.size(); ++index) {
      if (block.values[index].kind != Token::Kind::word || block.values[index].value != keyword) continue;
      for (++index; index < block.values.size(); ++index) {
        const auto number = parse_integer(block.values[index].value);
        if (!number) break;
        numbers.push_back(*number);
      }
      break;
    }
    return numbers;
  }

  // COMPU_METHODs, RECORD_LAYOUTs and TYPEDEFs by name, for what refers to them.
  void index_definitions(const Block& block) {
    if (block.keyword == "COMPU_METHOD") {
      read_compu_method(block);
    } else if (block.keyword == "COMPU_VTAB") {
      read_verbal_table(block);
    } else if (block.keyword == "RECORD_LAYOUT") {
      read_record_layout(block);
    } else if (block.keyword.starts_with("TYPEDEF_") && !block.values.empty()) {
      typedefs_[block.values[0].value] = &block;
    }
  }

  void read_compu_method(const Block& block) {
    const Token* name = value(block, 0, "the conversion's name");
    const Token* type = value(block, 2, "the conversion type");
    if (name == nullptr || type == nullptr) return;
    CompuMethod method;
    if (block.values.size() >= 5) method.unit = block.values[4].value;
    if (const Token* unit = after(block, "REF_UNIT"); unit != nullptr && method.unit.empty()) {
      const auto found = units_.find(unit->value);
      method.unit = found != units_.end() ? found->second : unit->value;
    }
    if (type->value == "LINEAR") {
      const std::vector<double> coefficients = reals_after(block, "COEFFS_LINEAR", 2);
      if (coefficients.size() == 2) method.conversion = {coefficients[0], coefficients[1]};
    } else if (type->value == "RAT_FUNC") {
      // raw = (a p^2 + b p + c) / (d p^2 + e p + f): linear when a = d = e = 0, so p = (f raw - c) / b.
      const std::vector<double> c = reals_after(block, "COEFFS", 6);
      if (c.size() != 6 || c[0] != 0 || c[3] != 0 || c[4] != 0 || c[1] == 0) {
        warn(block.place,
             "COMPU_METHOD " + name->value + ": a RAT_FUNC that is not linear is not applied (raw values)");
        method.unapplied = "RAT_FUNC (not linear)";
      } else {
        method.conversion = {c[5] / c[1], -c[2] / c[1]};
      }
    } else if (const Token* table = after(block, "COMPU_TAB_REF"); type->value == "TAB_VERB" && table != nullptr) {
      method.verbal_table = table->value;
    } else if (type->value != "IDENTICAL") {
      warn(block.place,
           "COMPU_METHOD " + name->value + ": " + type->value + " conversions are not applied (raw values)");
      method.unapplied = type->value;
    }
    compu_methods_[name->value] = method;
  }

  // name LongIdentifier TAB_VERB NumberValuePairs, then the pairs: raw value, its text (DEFAULT_VALUE is left out).
  void read_verbal_table(const Block& block) {
    const Token* name = value(block, 0, "the table's name");
    const Token* pairs = value(block, 3, "the number of value pairs");
    if (name == nullptr || pairs == nullptr) return;
    const std::uint64_t count = integer(pairs).value_or(0);
    std::vector<Label> labels;
    for (std::size_t index = 4; labels.size() < count && index + 1 < block.values.size(); index += 2) {
      if (block.values[index].value.starts_with("DEFAULT_VALUE")) break;
      const std::optional<double> raw = real(&block.values[index]);
      if (!raw) return;
      labels.push_back({*raw, block.values[index + 1].value});
    }
    if (labels.size() != count) {
      fail(pairs->place, "COMPU_VTAB " + name->value + ": " + pairs->value + " value pairs announced, " +
                             std::to_string(labels.size()) + " follow");
      return;
    }
    verbal_tables_[name->value] = std::move(labels);
  }

  std::vector<Label> verbal_table(const std::string& name, const Token& conversion) {
    const auto table = verbal_tables_.find(name);
    if (table != verbal_tables_.end()) return table->second;
    fail(conversion.place, "COMPU_METHOD " + conversion.value + ": no COMPU_VTAB named '" + name + "'");
    return {};
  }

  std::vector<double> reals_after(const Block& block, std::string_view keyword, std::size_t count) {
    std::vector<double> numbers;
    for (std::size_t index = 0; index + count < block.values.size(); ++index) {
      if (block.values[index].value != keyword) continue;
      for (std::size_t item = 1; item <= count; ++item) {
        if (auto number = real(&block.values[index + item])) numbers.push_back(*number);
      }
      break;
    }
    return numbers;
  }

  // The items of a record layout with a position and a data type, and RESERVED with its size.
  void read_record_layout(const Block& block) {
    const Token* name = value(block, 0, "the layout's name");
    if (name == nullptr) return;
    RecordLayout layout;
    layout.block = &block;
    layout.alignments = alignments_in(block);
    const std::vector<Token>& values = block.values;
    for (std::size_t index = 1; index < values.size(); ++index) {
      const std::string& keyword = values[index].value;
      const bool positioned =
          keyword == "FNC_VALUES" || keyword.starts_with("AXIS_PTS_") || keyword.starts_with("NO_AXIS_PTS_") ||
          keyword.starts_with("SRC_ADDR_") || keyword.starts_with("RIP_ADDR_") || keyword.starts_with("SHIFT_OP_") ||
          keyword.starts_with("OFFSET_") || keyword.starts_with("DIST_OP_") || keyword == "IDENTIFICATION";
      if (keyword == "RESERVED" && index + 2 < values.size()) {
        const std::string& size = values[index + 2].value;
        const std::size_t bytes = size == "BYTE" ? 1 : size == "WORD" ? 2 : size == "LONG" ? 4 : 8;
        layout.items.push_back({keyword, integer(&values[index + 1]).value_or(0), bytes, DataType::uint8});
      } else if (positioned && index + 2 < values.size()) {
        const auto type = data_type(&values[index + 2]).value_or(DataType::uint8);
        layout.items.push_back({keyword, integer(&values[index + 1]).value_or(0), size_of(type), type});
        if (keyword == "FNC_VALUES" && index + 4 < values.size()) {
          layout.direct = values[index + 4].value == "DIRECT";
          if (values[index + 3].value.starts_with("ALTERNATE")) {
            warn(block.place, "RECORD_LAYOUT " + name->value + ": " + values[index + 3].value +
                                  " (values between axis points) is read as if the values were together");
          }
        }
      } else if (keyword.starts_with("AXIS_RESCALE_")) {
        warn(block.place, "RECORD_LAYOUT " + name->value + ": " + keyword + " is not read");
      }
    }
    std::stable_sort(layout.items.begin(), layout.items.end(),
                     [](const LayoutItem& left, const LayoutItem& right) { return left.position < right.position; });
    record_layouts_[name->value] = std::move(layout);
  }

  void read_module_parameters(const Block& parameters) {
    if (const Token* epk = after(parameters, "EPK")) a2l.epk = epk->value;
    if (const Token* address = after(parameters, "ADDR_EPK"))
      a2l.epk_address = static_cast<std::uint32_t>(integer(address).value_or(0));
    for (const Block& segment : parameters.children) {
      if (segment.keyword != "MEMORY_SEGMENT") continue;
      MemoryInfo memory;
      if (const Token* name = value(segment, 0, "the segment's name")) memory.name = name->value;
      memory.address = static_cast<std::uint32_t>(integer(value(segment, 5, "the segment's address")).value_or(0));
      memory.size = static_cast<std::uint32_t>(integer(value(segment, 6, "the segment's size")).value_or(0));
      if (const Block* xcp = child(segment, "IF_DATA")) {
        if (const Block* paged = child(*xcp, "SEGMENT")) read_calibration_segment(*paged, memory);
      }
      a2l.memory.push_back(memory);
    }
  }

  void read_calibration_segment(const Block& segment, MemoryInfo& memory) {
    memory.calibration = true;
    const auto pages = integer(value(segment, 1, "the number of pages")).value_or(2);
    memory.extension = static_cast<std::uint8_t>(integer(value(segment, 2, "the address extension")).value_or(0));
    a2l.calibration_reference_page = pages >= 2;
    if (const Block* checksum = child(segment, "CHECKSUM"); checksum != nullptr && !checksum->values.empty()) {
      constexpr std::pair<std::string_view, ChecksumType> types[] = {
          {"XCP_ADD_11", ChecksumType::add_11}, {"XCP_ADD_12", ChecksumType::add_12},
          {"XCP_ADD_14", ChecksumType::add_14}, {"XCP_ADD_22", ChecksumType::add_22},
          {"XCP_ADD_24", ChecksumType::add_24}, {"XCP_ADD_44", ChecksumType::add_44},
          {"XCP_CRC_16", ChecksumType::crc_16}, {"XCP_CRC_16_CITT", ChecksumType::crc_16_ccitt},
          {"XCP_CRC_32", ChecksumType::crc_32}};
      for (const auto& [keyword, type] : types) {
        if (checksum->values[0].value == keyword) a2l.checksum_type = type;
      }
      if (const Token* size = after(*checksum, "MAX_BLOCK_SIZE"))
        a2l.checksum_max_block_size = static_cast<std::uint32_t>(integer(size).value_or(0));
    }
  }

  void read_module_common(const Block& common) {
    module_alignments_ = alignments_in(common);
    const Token* order = after(common, "BYTE_ORDER");
    if (order != nullptr && (order->value == "MSB_FIRST" || order->value == "BIG_ENDIAN")) {
      warn(order->place, "big-endian values (" + order->value + ") are read as little-endian");
    }
  }

  void read_xcp(const Block& xcp) {
    if (const Block* protocol = child(xcp, "PROTOCOL_LAYER")) {
      a2l.max_cto = static_cast<std::uint8_t>(integer(value(*protocol, 8, "MAX_CTO")).value_or(8));
      a2l.max_dto = static_cast<std::uint16_t>(integer(value(*protocol, 9, "MAX_DTO")).value_or(8));
      for (std::size_t index = 0; index + 1 < protocol->values.size(); ++index) {
        if (protocol->values[index].value == "OPTIONAL_CMD" && protocol->values[index + 1].value == "USER_CMD")
          a2l.user_command = true;
      }
    }
    if (const Block* daq = child(xcp, "DAQ")) read_daq(*daq);
    for (std::string_view keyword : {"XCP_ON_TCP_IP", "XCP_ON_UDP_IP"}) {
      if (const Block* transport = child(xcp, keyword)) {
        a2l.transport.protocol = keyword == "XCP_ON_TCP_IP" ? Protocol::tcp : Protocol::udp;
        a2l.transport.port = static_cast<std::uint16_t>(integer(value(*transport, 1, "the port")).value_or(5555));
        if (const Token* host = after(*transport, "ADDRESS")) a2l.transport.host = host->value;
        if (const Token* host = after(*transport, "HOST_NAME")) a2l.transport.host = host->value;
      }
    }
  }

  void read_daq(const Block& daq) {
    a2l.max_daq_lists = static_cast<std::uint16_t>(integer(value(daq, 1, "MAX_DAQ")).value_or(0));
    if (const Token* field = value(daq, 6, "IDENTIFICATION_FIELD")) {
      constexpr std::pair<std::string_view, IdentificationField> fields[] = {
          {"IDENTIFICATION_FIELD_TYPE_ABSOLUTE", IdentificationField::absolute},
          {"IDENTIFICATION_FIELD_TYPE_RELATIVE_BYTE", IdentificationField::relative_byte},
          {"IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD", IdentificationField::relative_word},
          {"IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD_ALIGNED", IdentificationField::relative_word_aligned}};
      for (const auto& [keyword, identification] : fields) {
        if (field->value == keyword) a2l.identification_field = identification;
      }
    }
    a2l.max_odt_entry_size = static_cast<std::uint8_t>(integer(value(daq, 8, "MAX_ODT_ENTRY_SIZE_DAQ")).value_or(0xFF));
    a2l.timestamp_size = 0;
    for (const Block& inner : daq.children) {
      if (inner.keyword == "TIMESTAMP_SUPPORTED") {
        a2l.timestamp_ticks = static_cast<std::uint16_t>(integer(value(inner, 0, "TIMESTAMP_TICKS")).value_or(1));
        if (const Token* size = value(inner, 1, "the timestamp size")) {
          a2l.timestamp_size = size->value == "SIZE_BYTE" ? 1 : size->value == "SIZE_WORD" ? 2 : 4;
          if (size->value == "NO_TIME_STAMP") a2l.timestamp_size = 0;
        }
        if (const Token* unit = value(inner, 2, "the timestamp unit")) {
          for (std::size_t code = 0; code < std::size(time_units); ++code) {
            if (unit->value == time_units[code]) a2l.timestamp_unit = static_cast<std::uint8_t>(code);
          }
        }
      } else if (inner.keyword == "EVENT") {
        EventInfo event;
        if (const Token* name = value(inner, 0, "the event's name")) event.name = name->value;
        if (const Token* name = value(inner, 1, "the event's short name")) event.short_name = name->value;
        event.channel = static_cast<std::uint16_t>(integer(value(inner, 2, "the event channel")).value_or(0));
        event.time_cycle = static_cast<std::uint8_t>(integer(value(inner, 5, "TIME_CYCLE")).value_or(0));
        event.time_unit = static_cast<std::uint8_t>(integer(value(inner, 6, "TIME_UNIT")).value_or(0));
        event.priority = static_cast<std::uint8_t>(integer(value(inner, 7, "PRIORITY")).value_or(0));
        a2l.events.push_back(event);
      }
    }
  }

  void read_module_block(const Block& block) {
    static const std::vector<std::string_view> read_elsewhere{
        "MOD_PAR",   "MOD_COMMON", "IF_DATA",          "COMPU_METHOD", "RECORD_LAYOUT", "UNIT",     "AXIS_PTS",
        "COMPU_TAB", "COMPU_VTAB", "COMPU_VTAB_RANGE", "A2ML",         "GROUP",         "FUNCTION", "USER_RIGHTS"};
    if (block.keyword == "MEASUREMENT") {
      if (auto variable = measurement(block, std::nullopt)) a2l.measurements.push_back(*variable);
    } else if (block.keyword == "CHARACTERISTIC") {
      if (auto variable = characteristic(block, std::nullopt)) a2l.characteristics.push_back(*variable);
    } else if (block.keyword == "INSTANCE") {
      read_instance(block);
    } else if (!block.keyword.starts_with("TYPEDEF_") &&
               std::find(read_elsewhere.begin(), read_elsewhere.end(), block.keyword) == read_elsewhere.end()) {
      warn(block.place, block.keyword + " is not read");
    }
  }

  // The array's dimensions from MATRIX_DIM (ARRAY_SIZE and NUMBER in older files); trailing 1s of the 3-number form
  // of ASAP2 1.6 are no dimension.
  static void set_dimensions(Variable& variable, std::vector<std::uint64_t> dimensions) {
    while (dimensions.size() > 1 && dimensions.back() == 1) dimensions.pop_back();
    std::uint64_t count = 1;
    for (std::uint64_t dimension : dimensions) count *= dimension;
    variable.count = static_cast<std::uint32_t>(count);
    variable.dimensions.clear();
    if (dimensions.size() > 1) {
      for (std::uint64_t dimension : dimensions) variable.dimensions.push_back(static_cast<std::uint32_t>(dimension));
    }
  }

  // Shared by every kind: address extension, unit, array size, conversion, and what the reader leaves out.
  void finish(const Block& block, Variable& variable, const Token* conversion) {
    if (const Token* extension = after(block, "ECU_ADDRESS_EXTENSION"))
      variable.extension = static_cast<std::uint8_t>(integer(extension).value_or(0));
    for (std::string_view keyword : {"MATRIX_DIM", "ARRAY_SIZE", "NUMBER"}) {
      std::vector<std::uint64_t> dimensions = numbers_after(block, keyword);
      if (!dimensions.empty()) {
        set_dimensions(variable, std::move(dimensions));
        break;
      }
    }
    if (conversion != nullptr) {
      const auto method = compu_methods_.find(conversion->value);
      if (method != compu_methods_.end()) {
        variable.conversion = method->second.conversion;
        variable.unapplied_conversion = method->second.unapplied;
        variable.unit = method->second.unit;
        if (!method->second.verbal_table.empty())
          variable.labels = verbal_table(method->second.verbal_table, *conversion);
      } else if (conversion->value != "NO_COMPU_METHOD") {
        fail(conversion->place, variable.name + ": no COMPU_METHOD named '" + conversion->value + "'");
      }
    }
    if (const Token* unit = after(block, "PHYS_UNIT")) variable.unit = unit->value;
    if (const Token* mask = after(block, "BIT_MASK")) {
      warn(mask->place, variable.name + ": BIT_MASK " + mask->value + " is not applied (the whole value is read)");
    }
    if (const Token* order = after(block, "BYTE_ORDER");
        order != nullptr && order->value != "MSB_LAST" && order->value != "LITTLE_ENDIAN") {
      warn(order->place, variable.name + ": big-endian values (" + order->value + ") are read as little-endian");
    }
  }

  // A MEASUREMENT, or a TYPEDEF_MEASUREMENT placed at `address` (the same values in the same places).
  std::optional<Variable> measurement(const Block& block, std::optional<std::uint32_t> address) {
    Variable variable;
    if (const Token* name = value(block, 0, "the name")) variable.name = name->value;
    if (const Token* description = value(block, 1, "the description")) variable.description = description->value;
    variable.type = data_type(value(block, 2, "the data type")).value_or(DataType::uint8);
    variable.minimum = real(value(block, 6, "the lower limit")).value_or(0);
    variable.maximum = real(value(block, 7, "the upper limit")).value_or(0);
    finish(block, variable, value(block, 3, "the conversion"));
    if (child(block, "VIRTUAL") != nullptr) {
      warn(block.place, variable.name + ": a VIRTUAL measurement (computed by the master) is left out");
      return std::nullopt;
    }
    if (address) {
      variable.address = *address;
    } else if (const Token* found = after(block, "ECU_ADDRESS")) {
      variable.address = static_cast<std::uint32_t>(integer(found).value_or(0));
    } else {
      warn(block.place, variable.name + ": no ECU_ADDRESS, left out");
      return std::nullopt;
    }
    return variable;
  }

  const RecordLayout* layout(const Token* name, const std::string& user) {
    if (name == nullptr) return nullptr;
    const auto found = record_layouts_.find(name->value);
    if (found != record_layouts_.end()) return &found->second;
    fail(name->place, user + ": no RECORD_LAYOUT named '" + name->value + "'");
    return nullptr;
  }

  // The alignment of a type in a record: the layout's ALIGNMENT_*, else MOD_COMMON's, else its own size.
  [[nodiscard]] std::size_t alignment(const RecordLayout& record, DataType type) const {
    const std::string_view keyword = alignment_keyword(type);
    if (const auto own = record.alignments.find(keyword); own != record.alignments.end()) return own->second;
    if (const auto common = module_alignments_.find(keyword); common != module_alignments_.end()) return common->second;
    return size_of(type);
  }

  // Where each item of a record starts, from the record's start: items in order of position, each `count` elements
  // (the values: all of them, an axis: its points), each aligned as its type is.
  [[nodiscard]] std::map<std::string, std::size_t> offsets(const RecordLayout& record, std::size_t values,
                                                           const std::vector<std::uint32_t>& axis_points) const {
    std::map<std::string, std::size_t> result;
    std::size_t offset = 0;
    for (const LayoutItem& item : record.items) {
      const std::size_t align = item.keyword == "RESERVED" ? 1 : alignment(record, item.type);
      offset = (offset + align - 1) / align * align;
      result[item.keyword] = offset;
      std::size_t count = 1;
      if (item.keyword == "FNC_VALUES") count = values;
      if (item.keyword.starts_with("AXIS_PTS_")) {
        constexpr std::string_view axes = "XYZ45";
        const std::size_t axis = axes.find(item.keyword.back());
        count = axis < axis_points.size() ? axis_points[axis] : 1;
      }
      offset += count * item.element_size;
    }
    return result;
  }

  static const LayoutItem* item(const RecordLayout& record, std::string_view keyword) {
    for (const LayoutItem& candidate : record.items) {
      if (candidate.keyword == keyword) return &candidate;
    }
    return nullptr;
  }

  // A CHARACTERISTIC, or a TYPEDEF_CHARACTERISTIC placed at `placed` (it has no address, so the values after the
  // type move one place up): its values, and for a CURVE, MAP, CUBOID ... its axes, one AXIS_DESCR each, the values'
  // count the product of their points.
  std::optional<Variable> characteristic(const Block& block, std::optional<std::uint32_t> placed) {
    const std::size_t shift = placed ? 1 : 0;
    struct {
      std::size_t deposit, conversion, lower, upper;
    } const at{4 - shift, 6 - shift, 7 - shift, 8 - shift};
    Variable variable;
    if (const Token* name = value(block, 0, "the name")) variable.name = name->value;
    if (const Token* description = value(block, 1, "the description")) variable.description = description->value;
    const Token* kind = value(block, 2, "the type");
    const std::uint32_t address =
        placed ? *placed : static_cast<std::uint32_t>(integer(value(block, 3, "the address")).value_or(0));
    const RecordLayout* record = layout(value(block, at.deposit, "the record layout"), variable.name);
    variable.minimum = real(value(block, at.lower, "the lower limit")).value_or(0);
    variable.maximum = real(value(block, at.upper, "the upper limit")).value_or(0);
    finish(block, variable, value(block, at.conversion, "the conversion"));
    if (kind == nullptr || record == nullptr) return std::nullopt;
    const LayoutItem* values = item(*record, "FNC_VALUES");
    if (values == nullptr || !record->direct) {
      warn(block.place, variable.name + ": its RECORD_LAYOUT has no FNC_VALUES read DIRECT, left out");
      return std::nullopt;
    }
    variable.type = values->type;
    if (kind->value == "ASCII") variable.type = DataType::uint8;
    constexpr std::string_view axes = "XYZ45";
    std::vector<std::uint32_t> points;
    for (const Block& axis_block : block.children) {
      if (axis_block.keyword != "AXIS_DESCR") continue;
      Axis described = axis(axis_block, variable.name);
      // A record with a fixed number of points (FIX_NO_AXIS_PTS_X) holds that many, not MaxAxisPoints.
      if (described.kind == Axis::Kind::standard && variable.axes.size() < axes.size()) {
        const auto fixed = numbers_after(*record->block, std::string{"FIX_NO_AXIS_PTS_"} + axes[variable.axes.size()]);
        if (!fixed.empty()) described.points = static_cast<std::uint32_t>(fixed.front());
      }
      points.push_back(described.points);
      variable.axes.push_back(std::move(described));
    }
    if (!points.empty()) {
      set_dimensions(variable, {points.begin(), points.end()});
      if (points.size() == 1) variable.dimensions.clear();
    }
    const auto where = offsets(*record, variable.count, points);
    variable.address = address + static_cast<std::uint32_t>(where.at("FNC_VALUES"));
    for (std::size_t index = 0; index < variable.axes.size() && index < axes.size(); ++index) {
      Axis& described = variable.axes[index];
      if (described.kind != Axis::Kind::standard) continue;
      const std::string keyword = std::string{"AXIS_PTS_"} + axes[index];
      const LayoutItem* points_item = item(*record, keyword);
      if (points_item == nullptr) {
        warn(block.place, variable.name + ": a STD_AXIS without " + keyword + " in its RECORD_LAYOUT");
        continue;
      }
      described.type = points_item->type;
      described.address = address + static_cast<std::uint32_t>(where.at(keyword));
    }
    return variable;
  }

  Axis axis(const Block& block, const std::string& user) {
    Axis described;
    const Token* kind = value(block, 0, "the axis type");
    if (const Token* input = value(block, 1, "the input quantity")) described.input = input->value;
    described.points = static_cast<std::uint32_t>(integer(value(block, 3, "MaxAxisPoints")).value_or(0));
    if (kind == nullptr) return described;
    if (kind->value == "COM_AXIS" || kind->value == "RES_AXIS") {
      described.kind = kind->value == "COM_AXIS" ? Axis::Kind::common : Axis::Kind::rescale;
      if (const Token* reference = after(block, "AXIS_PTS_REF")) {
        described.reference = reference->value;
        const auto found = std::find_if(a2l.characteristics.begin(), a2l.characteristics.end(),
                                        [&](const Variable& axis) { return axis.name == reference->value; });
        if (found == a2l.characteristics.end()) {
          fail(reference->place, user + ": no AXIS_PTS named '" + reference->value + "'");
        } else {
          described.type = found->type;
          described.address = found->address;
        }
      }
    } else if (kind->value == "CURVE_AXIS") {
      described.kind = Axis::Kind::curve;
      if (const Token* reference = after(block, "CURVE_AXIS_REF")) described.reference = reference->value;
    } else if (kind->value == "FIX_AXIS") {
      described.kind = Axis::Kind::fixed;
      for (std::string_view keyword : {"FIX_AXIS_PAR", "FIX_AXIS_PAR_DIST"}) {
        const std::vector<std::uint64_t> numbers = numbers_after(block, keyword);
        if (numbers.size() >= 3) described.points = static_cast<std::uint32_t>(numbers[2]);
      }
      if (const Block* list = child(block, "FIX_AXIS_PAR_LIST"))
        described.points = static_cast<std::uint32_t>(list->values.size());
    }
    return described;
  }

  // An AXIS_PTS (or a TYPEDEF_AXIS placed at `address`): its points as a parameter a master can read and tune.
  std::optional<Variable> axis_points(const Block& block, std::optional<std::uint32_t> placed) {
    const std::size_t shift = placed ? 1 : 0;
    Variable variable;
    if (const Token* name = value(block, 0, "the name")) variable.name = name->value;
    if (const Token* description = value(block, 1, "the description")) variable.description = description->value;
    const std::uint32_t address =
        placed ? *placed : static_cast<std::uint32_t>(integer(value(block, 2, "the address")).value_or(0));
    const RecordLayout* record = layout(value(block, 4 - shift, "the record layout"), variable.name);
    const auto points = integer(value(block, 7 - shift, "MaxAxisPoints")).value_or(1);
    variable.minimum = real(value(block, 8 - shift, "the lower limit")).value_or(0);
    variable.maximum = real(value(block, 9 - shift, "the upper limit")).value_or(0);
    finish(block, variable, value(block, 6 - shift, "the conversion"));
    if (record == nullptr) return std::nullopt;
    const LayoutItem* points_item = item(*record, "AXIS_PTS_X");
    if (points_item == nullptr) {
      warn(block.place, variable.name + ": its RECORD_LAYOUT has no AXIS_PTS_X, left out");
      return std::nullopt;
    }
    variable.type = points_item->type;
    variable.count = static_cast<std::uint32_t>(points);
    variable.dimensions.clear();
    variable.address = address + static_cast<std::uint32_t>(
                                     offsets(*record, 0, {static_cast<std::uint32_t>(points)}).at("AXIS_PTS_X"));
    return variable;
  }

  // An INSTANCE of a TYPEDEF_*: a structure's components become "instance.component" at base + offset.
  void read_instance(const Block& block) {
    const Token* name = value(block, 0, "the instance's name");
    const Token* type = value(block, 2, "the instance's type");
    const auto address = integer(value(block, 3, "the instance's address"));
    if (name == nullptr || type == nullptr || !address) return;
    const std::vector<std::uint64_t> dimensions = numbers_after(block, "MATRIX_DIM");
    std::uint8_t extension = 0;
    if (const Token* found = after(block, "ECU_ADDRESS_EXTENSION"))
      extension = static_cast<std::uint8_t>(integer(found).value_or(0));
    place(name->value, *type, static_cast<std::uint32_t>(*address), extension, dimensions, block.place, 0);
  }

  void place(const std::string& name, const Token& type, std::uint32_t address, std::uint8_t extension,
             const std::vector<std::uint64_t>& dimensions, const Place& at, std::size_t depth) {
    const auto found = typedefs_.find(type.value);
    if (found == typedefs_.end()) {
      fail(type.place, name + ": no TYPEDEF named '" + type.value + "'");
      return;
    }
    const Block& definition = *found->second;
    std::optional<Variable> variable;
    if (definition.keyword == "TYPEDEF_STRUCTURE") {
      if (depth >= max_structure_depth) {
        fail(at, name + ": structures nest deeper than " + std::to_string(max_structure_depth) + " (a loop?)");
        return;
      }
      if (!dimensions.empty()) {
        warn(at, name + ": an array of structures (" + type.value + ") is not expanded");
        return;
      }
      for (const Block& component : definition.children) {
        if (component.keyword != "STRUCTURE_COMPONENT") continue;
        const Token* member = value(component, 0, "the component's name");
        const Token* member_type = value(component, 1, "the component's type");
        const auto offset = integer(value(component, 2, "the component's offset"));
        if (member == nullptr || member_type == nullptr || !offset) return;
        place(name + "." + member->value, *member_type, address + static_cast<std::uint32_t>(*offset), extension,
              numbers_after(component, "MATRIX_DIM"), component.place, depth + 1);
      }
      return;
    }
    if (definition.keyword == "TYPEDEF_MEASUREMENT") {
      variable = measurement(definition, address);
    } else if (definition.keyword == "TYPEDEF_CHARACTERISTIC") {
      variable = characteristic(definition, address);
    } else if (definition.keyword == "TYPEDEF_AXIS") {
      variable = axis_points(definition, address);
    } else {
      warn(at, name + ": an instance of " + definition.keyword + " is not read");
      return;
    }
    if (!variable) return;
    variable->name = name;
    variable->extension = extension;
    if (!dimensions.empty() && variable->axes.empty()) set_dimensions(*variable, dimensions);
    if (definition.keyword == "TYPEDEF_MEASUREMENT") {
      a2l.measurements.push_back(*variable);
    } else {
      a2l.characteristics.push_back(*variable);
    }
  }

  const a2l_syntax::Tree& tree_;
  std::map<std::string, CompuMethod, std::less<>> compu_methods_;
  std::map<std::string, std::vector<Label>, std::less<>> verbal_tables_;
  std::map<std::string, RecordLayout, std::less<>> record_layouts_;
  std::map<std::string, std::string, std::less<>> units_;
  Alignments module_alignments_;
  std::map<std::string, const Block*, std::less<>> typedefs_;
};

}  // namespace

Result<A2lDescription> read_a2l(std::string_view text, std::string_view source) {
  auto parsed = a2l_syntax::parse(text, source);
  if (auto* failed = std::get_if<a2l_syntax::SyntaxError>(&parsed)) return Failure{failed->message()};
  const a2l_syntax::Tree& tree = std::get<a2l_syntax::Tree>(parsed);
  const Block* project = child(tree.root, "PROJECT");
  if (project == nullptr) return Failure{std::string{source} + ":1:1: no /begin PROJECT"};
  const Block* module = child(*project, "MODULE");
  if (module == nullptr) return Failure{tree.where(project->place) + ": PROJECT has no MODULE"};
  Reader reader{tree};
  if (!project->values.empty()) reader.a2l.project = project->values[0].value;
  reader.read_module(*module);
  for (const Block& other : project->children) {
    if (other.keyword == "MODULE" && &other != module) reader.warn(other.place, "only the first MODULE is read");
  }
  if (reader.error) return Failure{*reader.error};
  return std::move(reader.a2l);
}

Result<A2lDescription> read_a2l_file(const std::string& path) {
  auto text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return read_a2l(text.value(), path);
}

double seconds_per_unit(std::uint8_t code) {
  static constexpr double seconds[] = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0};
  return code < std::size(seconds) ? seconds[code] : 1e-6;
}

std::size_t size_of(DataType type) {
  switch (type) {
    case DataType::uint8:
    case DataType::int8: return 1;
    case DataType::uint16:
    case DataType::int16: return 2;
    case DataType::uint32:
    case DataType::int32:
    case DataType::float32: return 4;
    case DataType::uint64:
    case DataType::int64:
    case DataType::float64: return 8;
  }
  return 0;
}

std::string_view a2l_name(DataType type) {
  switch (type) {
    case DataType::uint8: return "UBYTE";
    case DataType::int8: return "SBYTE";
    case DataType::uint16: return "UWORD";
    case DataType::int16: return "SWORD";
    case DataType::uint32: return "ULONG";
    case DataType::int32: return "SLONG";
    case DataType::uint64: return "A_UINT64";
    case DataType::int64: return "A_INT64";
    case DataType::float32: return "FLOAT32_IEEE";
    case DataType::float64: return "FLOAT64_IEEE";
  }
  return "UBYTE";
}

}  // namespace duet::xcp::host
