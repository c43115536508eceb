// Reads A2L text into an A2lDescription: a tokenizer, a tree of /begin ... /end blocks, then the parts duet uses.

#include <charconv>
#include <cstdlib>
#include <map>
#include <optional>
#include <variant>

#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

struct Token {
  enum class Kind : std::uint8_t { word, text, begin, end };
  Kind kind = Kind::word;
  std::string value;
  std::size_t line = 1;
  std::size_t column = 1;
};

struct Block {
  std::string keyword;
  std::vector<Token> values;  // the words and texts directly inside, in order
  std::vector<Block> children;
  std::size_t line = 1;
  std::size_t column = 1;
};

class A2lError {
 public:
  A2lError(std::string_view source, std::size_t line, std::size_t column, const std::string& problem)
      : message_(std::string{source} + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + problem) {}
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  std::string message_;
};

// Splits the text into words, "texts", /begin and /end; comments (/* */ and //) are dropped.
std::variant<std::vector<Token>, A2lError> tokenize(std::string_view text, std::string_view source) {
  std::vector<Token> tokens;
  std::size_t line = 1;
  std::size_t column = 1;
  std::size_t at = 0;
  auto advance = [&](std::size_t count) {
    for (std::size_t step = 0; step < count && at < text.size(); ++step, ++at) {
      if (text[at] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
  };
  while (at < text.size()) {
    const char character = text[at];
    if (character == ' ' || character == '\t' || character == '\r' || character == '\n') {
      advance(1);
    } else if (text.substr(at, 2) == "/*") {
      const std::size_t close = text.find("*/", at + 2);
      if (close == std::string_view::npos) return A2lError{source, line, column, "a comment that never ends"};
      advance(close + 2 - at);
    } else if (text.substr(at, 2) == "//") {
      const std::size_t newline = text.find('\n', at);
      advance((newline == std::string_view::npos ? text.size() : newline) - at);
    } else if (character == '"') {
      Token token{Token::Kind::text, "", line, column};
      advance(1);
      for (;;) {
        if (at >= text.size()) return A2lError{source, token.line, token.column, "a text that never ends"};
        if (text[at] == '\\' && at + 1 < text.size()) {
          token.value += text[at + 1];
          advance(2);
        } else if (text[at] == '"' && at + 1 < text.size() && text[at + 1] == '"') {  // "" inside a text
          token.value += '"';
          advance(2);
        } else if (text[at] == '"') {
          advance(1);
          break;
        } else {
          token.value += text[at];
          advance(1);
        }
      }
      tokens.push_back(std::move(token));
    } else {
      Token token{Token::Kind::word, "", line, column};
      while (at < text.size() && text[at] != ' ' && text[at] != '\t' && text[at] != '\r' && text[at] != '\n' &&
             text[at] != '"') {
        token.value += text[at];
        advance(1);
      }
      if (token.value == "/begin") token.kind = Token::Kind::begin;
      if (token.value == "/end") token.kind = Token::Kind::end;
      tokens.push_back(std::move(token));
    }
  }
  return tokens;
}

// Builds the block tree; the root holds the top-level words (ASAP2_VERSION ...) and blocks (PROJECT).
std::variant<Block, A2lError> parse_blocks(const std::vector<Token>& tokens, std::string_view source) {
  Block root{"", {}, {}, 1, 1};
  std::vector<Block*> open{&root};
  std::vector<Block> storage;
  for (std::size_t index = 0; index < tokens.size(); ++index) {
    const Token& token = tokens[index];
    if (token.kind == Token::Kind::begin || token.kind == Token::Kind::end) {
      if (index + 1 >= tokens.size() || tokens[index + 1].kind != Token::Kind::word) {
        return A2lError{source, token.line, token.column, token.value + " without a keyword after it"};
      }
      const Token& keyword = tokens[++index];
      if (token.kind == Token::Kind::begin) {
        open.back()->children.push_back(Block{keyword.value, {}, {}, token.line, token.column});
        open.push_back(&open.back()->children.back());
      } else {
        if (open.size() == 1)
          return A2lError{source, token.line, token.column, "/end " + keyword.value + " without /begin"};
        if (open.back()->keyword != keyword.value) {
          return A2lError{source, token.line, token.column,
                          "/end " + keyword.value + " closes /begin " + open.back()->keyword + " (line " +
                              std::to_string(open.back()->line) + ")"};
        }
        open.pop_back();
      }
    } else {
      open.back()->values.push_back(token);
    }
  }
  if (open.size() > 1) {
    return A2lError{source, open.back()->line, open.back()->column,
                    "/begin " + open.back()->keyword + " is never closed"};
  }
  return root;
}

const Block* child(const Block& block, std::string_view keyword) {
  for (const Block& inner : block.children) {
    if (inner.keyword == keyword) return &inner;
  }
  return nullptr;
}

// What follows `keyword` among a block's values ("ECU_ADDRESS 0x1000"), if it is there.
const Token* after(const Block& block, std::string_view keyword, std::size_t skip = 0) {
  for (std::size_t index = skip; index + 1 < block.values.size(); ++index) {
    if (block.values[index].kind == Token::Kind::word && block.values[index].value == keyword)
      return &block.values[index + 1];
  }
  return nullptr;
}

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  std::optional<A2lError> error;

  [[nodiscard]] A2lError fail(const Token& token, const std::string& problem) const {
    return A2lError{source_, token.line, token.column, problem};
  }

  // The block's value at `index`, or an error naming the block and what was expected there.
  const Token* value(const Block& block, std::size_t index, std::string_view what) {
    if (index < block.values.size()) return &block.values[index];
    if (!error)
      error = A2lError{source_, block.line, block.column, block.keyword + ": " + std::string{what} + " is missing"};
    return nullptr;
  }

  std::optional<double> real(const Token* token) {
    if (token == nullptr) return std::nullopt;
    char* end = nullptr;
    const double parsed = std::strtod(token->value.c_str(), &end);
    if (end == token->value.c_str() || *end != '\0') {
      if (!error) error = fail(*token, "'" + token->value + "' is not a number");
      return std::nullopt;
    }
    return parsed;
  }

  std::optional<std::uint64_t> integer(const Token* token) {
    if (token == nullptr) return std::nullopt;
    std::string_view text = token->value;
    int base = 10;
    if (text.starts_with("0x") || text.starts_with("0X")) {
      text.remove_prefix(2);
      base = 16;
    }
    std::uint64_t parsed = 0;
    const auto [end, problem] = std::from_chars(text.data(), text.data() + text.size(), parsed, base);
    if (problem != std::errc{} || end != text.data() + text.size()) {
      if (!error) error = fail(*token, "'" + token->value + "' is not a whole number");
      return std::nullopt;
    }
    return parsed;
  }

  std::optional<DataType> data_type(const Token* token) {
    if (token == nullptr) return std::nullopt;
    for (DataType type : {DataType::uint8, DataType::int8, DataType::uint16, DataType::int16, DataType::uint32,
                          DataType::int32, DataType::uint64, DataType::int64, DataType::float32, DataType::float64}) {
      if (token->value == a2l_name(type)) return type;
    }
    if (!error) error = fail(*token, "'" + token->value + "' is not an A2L data type");
    return std::nullopt;
  }

 private:
  std::string_view source_;
};

struct CompuMethod {
  Conversion conversion;
  std::string unit;
};

}  // namespace

Result<A2lDescription> read_a2l(std::string_view text, std::string_view source) {
  auto tokens = tokenize(text, source);
  if (auto* failed = std::get_if<A2lError>(&tokens)) return Failure{failed->message()};
  auto tree = parse_blocks(std::get<std::vector<Token>>(tokens), source);
  if (auto* failed = std::get_if<A2lError>(&tree)) return Failure{failed->message()};
  const Block& root = std::get<Block>(tree);
  const Block* project = child(root, "PROJECT");
  if (project == nullptr) return Failure{std::string{source} + ":1:1: no /begin PROJECT"};
  const Block* module = child(*project, "MODULE");
  if (module == nullptr) {
    return Failure{std::string{source} + ":" + std::to_string(project->line) + ":" + std::to_string(project->column) +
                   ": PROJECT has no MODULE"};
  }
  Reader reader{source};
  A2lDescription a2l;
  if (const Token* name = reader.value(*project, 0, "the project's name")) a2l.project = name->value;
  if (const Token* name = reader.value(*module, 0, "the module's name")) a2l.module = name->value;
  if (module->values.size() > 1) a2l.description = module->values[1].value;

  std::map<std::string, CompuMethod, std::less<>> compu_methods;
  std::map<std::string, DataType, std::less<>> record_layouts;
  for (const Block& block : module->children) {
    if (block.keyword == "COMPU_METHOD" && block.values.size() >= 5) {
      CompuMethod method{{}, block.values[4].value};
      if (const Token* factor = after(block, "COEFFS_LINEAR")) {
        const auto parsed_factor = reader.real(factor);
        const auto parsed_offset = reader.real(after(block, factor->value, 5));
        if (parsed_factor && parsed_offset) method.conversion = {*parsed_factor, *parsed_offset};
      }
      compu_methods[block.values[0].value] = method;
    } else if (block.keyword == "RECORD_LAYOUT") {
      // name FNC_VALUES position datatype index_mode addressing
      const Token* name = reader.value(block, 0, "the layout's name");
      const Token* values = reader.value(block, 1, "FNC_VALUES");
      if (name != nullptr && values != nullptr && values->value == "FNC_VALUES") {
        if (auto type = reader.data_type(reader.value(block, 3, "the data type of FNC_VALUES")))
          record_layouts[name->value] = *type;
      }
    }
  }

  if (const Block* parameters = child(*module, "MOD_PAR")) {
    for (const Block& segment : parameters->children) {
      if (segment.keyword != "MEMORY_SEGMENT") continue;
      MemoryInfo memory;
      if (const Token* name = reader.value(segment, 0, "the segment's name")) memory.name = name->value;
      const auto address = reader.integer(reader.value(segment, 5, "the segment's address"));
      const auto size = reader.integer(reader.value(segment, 6, "the segment's size"));
      memory.address = static_cast<std::uint32_t>(address.value_or(0));
      memory.size = static_cast<std::uint32_t>(size.value_or(0));
      if (const Block* xcp = child(segment, "IF_DATA")) {
        if (const Block* paged = child(*xcp, "SEGMENT")) {
          memory.calibration = true;
          memory.extension =
              static_cast<std::uint8_t>(reader.integer(reader.value(*paged, 2, "the address extension")).value_or(0));
        }
      }
      a2l.memory.push_back(memory);
    }
  }

  if (const Block* xcp = child(*module, "IF_DATA")) {
    if (const Block* protocol = child(*xcp, "PROTOCOL_LAYER")) {
      a2l.max_cto = static_cast<std::uint8_t>(reader.integer(reader.value(*protocol, 8, "MAX_CTO")).value_or(8));
      a2l.max_dto = static_cast<std::uint16_t>(reader.integer(reader.value(*protocol, 9, "MAX_DTO")).value_or(8));
    }
    if (const Block* daq = child(*xcp, "DAQ")) {
      a2l.max_daq_lists = static_cast<std::uint16_t>(reader.integer(reader.value(*daq, 1, "MAX_DAQ")).value_or(0));
      for (const Block& inner : daq->children) {
        if (inner.keyword == "TIMESTAMP_SUPPORTED") {
          a2l.timestamp_ticks =
              static_cast<std::uint16_t>(reader.integer(reader.value(inner, 0, "TIMESTAMP_TICKS")).value_or(1));
          if (const Token* unit = reader.value(inner, 2, "the timestamp unit")) {
            constexpr std::string_view units[] = {"UNIT_1NS",   "UNIT_10NS", "UNIT_100NS", "UNIT_1US",   "UNIT_10US",
                                                  "UNIT_100US", "UNIT_1MS",  "UNIT_10MS",  "UNIT_100MS", "UNIT_1S"};
            for (std::size_t code = 0; code < std::size(units); ++code) {
              if (unit->value == units[code]) a2l.timestamp_unit = static_cast<std::uint8_t>(code);
            }
          }
        } else if (inner.keyword == "EVENT") {
          EventInfo event;
          if (const Token* name = reader.value(inner, 0, "the event's name")) event.name = name->value;
          event.channel =
              static_cast<std::uint16_t>(reader.integer(reader.value(inner, 2, "the event channel")).value_or(0));
          event.time_cycle =
              static_cast<std::uint8_t>(reader.integer(reader.value(inner, 5, "TIME_CYCLE")).value_or(0));
          event.time_unit = static_cast<std::uint8_t>(reader.integer(reader.value(inner, 6, "TIME_UNIT")).value_or(0));
          event.priority = static_cast<std::uint8_t>(reader.integer(reader.value(inner, 7, "PRIORITY")).value_or(0));
          a2l.events.push_back(event);
        }
      }
    }
    for (std::string_view keyword : {"XCP_ON_TCP_IP", "XCP_ON_UDP_IP"}) {
      if (const Block* transport = child(*xcp, keyword)) {
        a2l.transport.protocol = keyword == "XCP_ON_TCP_IP" ? Protocol::tcp : Protocol::udp;
        a2l.transport.port =
            static_cast<std::uint16_t>(reader.integer(reader.value(*transport, 1, "the port")).value_or(5555));
        if (const Token* host = after(*transport, "ADDRESS")) a2l.transport.host = host->value;
      }
    }
  }

  // Shared by MEASUREMENT and CHARACTERISTIC: address extension, unit, array size, conversion.
  auto finish = [&](const Block& block, Variable& variable, const Token* conversion) {
    if (const Token* extension = after(block, "ECU_ADDRESS_EXTENSION")) {
      variable.extension = static_cast<std::uint8_t>(reader.integer(extension).value_or(0));
    }
    const Token* dimension = after(block, "MATRIX_DIM");
    if (dimension == nullptr) dimension = after(block, "ARRAY_SIZE");
    if (dimension == nullptr) dimension = after(block, "NUMBER");
    if (dimension != nullptr) variable.count = static_cast<std::uint32_t>(reader.integer(dimension).value_or(1));
    if (conversion != nullptr) {
      const auto method = compu_methods.find(conversion->value);
      if (method != compu_methods.end()) {
        variable.conversion = method->second.conversion;
        variable.unit = method->second.unit;
      } else if (conversion->value != "NO_COMPU_METHOD" && !reader.error) {
        reader.error = reader.fail(*conversion, variable.name + ": no COMPU_METHOD named '" + conversion->value + "'");
      }
    }
    if (const Token* unit = after(block, "PHYS_UNIT")) variable.unit = unit->value;
  };

  for (const Block& block : module->children) {
    if (block.keyword == "MEASUREMENT") {
      Variable variable;
      if (const Token* name = reader.value(block, 0, "the name")) variable.name = name->value;
      if (const Token* description = reader.value(block, 1, "the description"))
        variable.description = description->value;
      variable.type = reader.data_type(reader.value(block, 2, "the data type")).value_or(DataType::uint8);
      variable.minimum = reader.real(reader.value(block, 6, "the lower limit")).value_or(0);
      variable.maximum = reader.real(reader.value(block, 7, "the upper limit")).value_or(0);
      if (const Token* address = after(block, "ECU_ADDRESS"))
        variable.address = static_cast<std::uint32_t>(reader.integer(address).value_or(0));
      finish(block, variable, reader.value(block, 3, "the conversion"));
      a2l.measurements.push_back(variable);
    } else if (block.keyword == "CHARACTERISTIC") {
      Variable variable;
      if (const Token* name = reader.value(block, 0, "the name")) variable.name = name->value;
      if (const Token* description = reader.value(block, 1, "the description"))
        variable.description = description->value;
      variable.address = static_cast<std::uint32_t>(reader.integer(reader.value(block, 3, "the address")).value_or(0));
      if (const Token* layout = reader.value(block, 4, "the record layout")) {
        const auto found = record_layouts.find(layout->value);
        if (found != record_layouts.end()) {
          variable.type = found->second;
        } else if (!reader.error) {
          reader.error = reader.fail(*layout, variable.name + ": no RECORD_LAYOUT named '" + layout->value + "'");
        }
      }
      variable.minimum = reader.real(reader.value(block, 7, "the lower limit")).value_or(0);
      variable.maximum = reader.real(reader.value(block, 8, "the upper limit")).value_or(0);
      finish(block, variable, reader.value(block, 6, "the conversion"));
      a2l.characteristics.push_back(variable);
    }
  }
  if (reader.error) return Failure{reader.error->message()};
  return a2l;
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
