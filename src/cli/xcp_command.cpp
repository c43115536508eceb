#include "xcp_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/values.hpp"
#include "duet/xcp/protocol.hpp"

namespace duet::cli {
namespace {

using nlohmann::json;
using namespace duet::xcp::host;

struct XcpOptions {
  std::string connect;
  std::string a2l_file;
  bool json = false;
  int timeout_ms = 1000;
  std::vector<std::string> targets;  // names, NAME=VALUE, or ADDRESS:SIZE
  std::vector<std::string> signals;
  std::string event;
  double duration_s = 1.0;
  std::string output;
  std::string address;
  std::uint32_t size = 0;
  int segment = 0;
  int page = -1;
  bool ecu = false;
  bool xcp = false;
};

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
  std::ostringstream out;
  for (std::size_t index = 0; index < bytes.size(); ++index) {
    out << (index == 0 ? "" : " ") << std::hex << std::uppercase << std::setw(2) << std::setfill('0')
        << static_cast<unsigned>(bytes[index]);
  }
  return out.str();
}

Result<A2lDescription> load_a2l(const std::string& file) {
  auto text = read_text_file(file);
  if (!text) return Failure{text.error()};
  return read_a2l(text.value(), file);
}

// Everything an action needs: the A2L (if given) and a connected master.
struct Session {
  std::optional<A2lDescription> a2l;
  std::unique_ptr<Master> master;
};

Result<Session> open_session(const XcpOptions& options, bool needs_master) {
  Session session;
  if (!options.a2l_file.empty()) {
    auto a2l = load_a2l(options.a2l_file);
    if (!a2l) return Failure{a2l.error()};
    session.a2l = std::move(a2l).value();
  }
  if (!needs_master) return session;
  Endpoint endpoint;
  if (!options.connect.empty()) {
    auto parsed = parse_endpoint(options.connect);
    if (!parsed) return Failure{parsed.error()};
    endpoint = parsed.value();
  } else if (session.a2l) {
    endpoint = session.a2l->transport;
  } else {
    return Failure{"no slave to talk to: give --connect tcp://host:port or --a2l FILE"};
  }
  const std::chrono::milliseconds timeout{options.timeout_ms};
  auto channel = MasterChannel::open(endpoint, timeout);
  if (!channel) return Failure{channel.error()};
  session.master = std::make_unique<Master>(std::move(channel).value(), timeout);
  if (auto connected = session.master->connect(); !connected) return Failure{connected.error()};
  return session;
}

const Variable* find_variable(const A2lDescription& a2l, const std::string& name) {
  for (const auto* list : {&a2l.measurements, &a2l.characteristics}) {
    for (const Variable& variable : *list) {
      if (variable.name == name) return &variable;
    }
  }
  return nullptr;
}

Result<const Variable*> variable_named(const Session& session, const std::string& name) {
  if (!session.a2l) return Failure{"'" + name + "': names need --a2l FILE"};
  const Variable* variable = find_variable(*session.a2l, name);
  if (variable == nullptr) return Failure{"'" + name + "' is neither a MEASUREMENT nor a CHARACTERISTIC in the A2L"};
  return variable;
}

Result<std::uint32_t> parse_number(const std::string& text) {
  try {
    std::size_t used = 0;
    const unsigned long value = std::stoul(text, &used, 0);
    if (used != text.size() || value > 0xFFFF'FFFFUL) throw std::invalid_argument{text};
    return static_cast<std::uint32_t>(value);
  } catch (const std::exception&) {
    return Failure{"'" + text + "' is not an address or size (decimal or 0x hex)"};
  }
}

ExitCode report(const Failure& failure, Streams streams) {
  streams.err << "duet xcp: " << failure.message << '\n';
  return ExitCode::failure;
}

ExitCode run_info(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  const SlaveProperties& slave = master.properties();
  auto id = master.identification(1);
  const std::string name = id ? std::string(id.value().begin(), id.value().end()) : std::string{};
  json info{{"identification", name},
            {"max_cto", slave.max_cto},
            {"max_dto", slave.max_dto},
            {"protocol_version", slave.protocol_version},
            {"transport_version", slave.transport_version},
            {"calibration_paging", (slave.resources & xcp::resource::calibration_paging) != 0},
            {"daq", (slave.resources & xcp::resource::daq) != 0}};
  (void)master.disconnect();
  if (options.json) {
    streams.out << info.dump(2) << '\n';
  } else {
    streams.out << "slave        " << name << "\nMAX_CTO      " << slave.max_cto + 0 << "\nMAX_DTO      "
                << slave.max_dto << "\nprotocol     " << slave.protocol_version + 0 << ", transport "
                << slave.transport_version + 0 << "\nresources    "
                << (info["calibration_paging"] ? "calibration/paging " : "") << (info["daq"] ? "DAQ" : "") << '\n';
  }
  return ExitCode::success;
}

ExitCode run_list(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, false);
  if (!session) return report({session.error()}, streams);
  if (!session.value().a2l) return report({"list needs --a2l FILE"}, streams);
  const A2lDescription& a2l = *session.value().a2l;
  json list = json::array();
  for (const auto& [kind, variables] :
       {std::pair{"measurement", &a2l.measurements}, std::pair{"characteristic", &a2l.characteristics}}) {
    for (const Variable& variable : *variables) {
      list.push_back({{"name", variable.name},
                      {"kind", kind},
                      {"type", std::string{a2l_name(variable.type)}},
                      {"address", variable.address},
                      {"count", variable.count},
                      {"unit", variable.unit},
                      {"min", variable.minimum},
                      {"max", variable.maximum},
                      {"description", variable.description}});
    }
  }
  if (options.json) {
    streams.out << list.dump(2) << '\n';
    return ExitCode::success;
  }
  for (const json& entry : list) {
    char address[16];
    std::snprintf(address, sizeof(address), "0x%08X", entry["address"].get<std::uint32_t>());
    streams.out << std::left << std::setw(24) << entry["name"].get<std::string>() << std::setw(15)
                << entry["kind"].get<std::string>() << std::setw(13) << entry["type"].get<std::string>() << address
                << "  " << entry["description"].get<std::string>() << '\n';
  }
  return ExitCode::success;
}

ExitCode run_read(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  json values = json::object();
  for (const std::string& target : options.targets) {
    const std::size_t colon = target.find(':');
    if (colon != std::string::npos) {  // ADDRESS:SIZE, raw bytes
      auto address = parse_number(target.substr(0, colon));
      auto size = parse_number(target.substr(colon + 1));
      if (!address) return report({address.error()}, streams);
      if (!size) return report({size.error()}, streams);
      auto bytes = master.upload(0, address.value(), size.value());
      if (!bytes) return report({bytes.error()}, streams);
      values[target] = hex_bytes(bytes.value());
      continue;
    }
    auto variable = variable_named(session.value(), target);
    if (!variable) return report({variable.error()}, streams);
    const Variable& found = *variable.value();
    auto bytes =
        master.upload(found.extension, found.address, static_cast<std::uint32_t>(size_of(found.type) * found.count));
    if (!bytes) return report({bytes.error()}, streams);
    const std::vector<double> decoded = decode(found, bytes.value());
    values[target] = found.count == 1 ? json(decoded.front()) : json(decoded);
  }
  (void)master.disconnect();
  if (options.json) {
    streams.out << values.dump(2) << '\n';
  } else {
    for (const auto& [name, value] : values.items()) streams.out << name << " = " << value.dump() << '\n';
  }
  return ExitCode::success;
}

ExitCode run_write(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  for (const std::string& assignment : options.targets) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos) return report({"'" + assignment + "': expected NAME=VALUE"}, streams);
    auto variable = variable_named(session.value(), assignment.substr(0, equals));
    if (!variable) return report({variable.error()}, streams);
    double value = 0;
    try {
      std::size_t used = 0;
      value = std::stod(assignment.substr(equals + 1), &used);
      if (used != assignment.size() - equals - 1) throw std::invalid_argument{assignment};
    } catch (const std::exception&) {
      return report({"'" + assignment + "': the value is not a number"}, streams);
    }
    auto bytes = encode(*variable.value(), value);
    if (!bytes) return report({bytes.error()}, streams);
    std::vector<std::uint8_t> all;
    for (std::uint32_t element = 0; element < variable.value()->count; ++element)
      all.insert(all.end(), bytes.value().begin(), bytes.value().end());
    if (Status written = master.download(variable.value()->extension, variable.value()->address, all); !written) {
      return report({written.error()}, streams);
    }
  }
  (void)master.disconnect();
  return ExitCode::success;
}

ExitCode run_record(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  if (!session.value().a2l) return report({"record needs --a2l FILE"}, streams);
  const A2lDescription& a2l = *session.value().a2l;
  Master& master = *session.value().master;
  std::uint16_t event = 0;
  bool event_found = false;
  for (const EventInfo& info : a2l.events) {
    if (info.name == options.event || std::to_string(info.channel) == options.event) {
      event = info.channel;
      event_found = true;
    }
  }
  if (!event_found)
    return report({"'" + options.event + "' is no event in the A2L (give its name or number)"}, streams);
  std::vector<const Variable*> recorded;
  DaqListSetup list{.event = event, .prescaler = 1};
  for (const std::string& name : options.signals) {
    auto variable = variable_named(session.value(), name);
    if (!variable) return report({variable.error()}, streams);
    recorded.push_back(variable.value());
    for (std::uint32_t element = 0; element < variable.value()->count; ++element) {
      list.entries.push_back(
          {variable.value()->extension,
           variable.value()->address + element * static_cast<std::uint32_t>(size_of(variable.value()->type)),
           static_cast<std::uint8_t>(size_of(variable.value()->type))});
    }
  }
  if (Status started = master.start_daq({list}); !started) return report({started.error()}, streams);

  std::ofstream file;
  if (!options.output.empty()) {
    file.open(options.output);
    if (!file) return report({options.output + ": cannot be written"}, streams);
  }
  std::ostream& csv = options.output.empty() ? streams.out : file;
  csv << "time_s";
  for (const Variable* variable : recorded) {
    for (std::uint32_t element = 0; element < variable->count; ++element) {
      csv << ',' << variable->name << (variable->count > 1 ? "[" + std::to_string(element) + "]" : "");
    }
  }
  csv << '\n';
  static constexpr double unit_seconds[] = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0};
  const double tick_seconds = unit_seconds[a2l.timestamp_unit < 10 ? a2l.timestamp_unit : 3] * a2l.timestamp_ticks;
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && &streams.err == &std::cerr;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(options.duration_s);
  std::optional<std::uint32_t> first_timestamp;
  std::uint64_t samples = 0;
  int last_second = -1;
  while (std::chrono::steady_clock::now() < end) {
    auto received = master.receive_samples(std::chrono::milliseconds{50});
    if (!received) return report({received.error()}, streams);
    for (const DaqSample& sample : received.value()) {
      if (!first_timestamp) first_timestamp = sample.timestamp;
      csv << std::setprecision(9) << static_cast<double>(sample.timestamp - *first_timestamp) * tick_seconds;
      std::size_t at = 0;
      for (const Variable* variable : recorded) {
        const std::size_t bytes = size_of(variable->type) * variable->count;
        for (double value : decode(*variable, std::span{sample.bytes}.subspan(at, bytes)))
          csv << ',' << std::setprecision(10) << value;
        at += bytes;
      }
      csv << '\n';
      ++samples;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (terminal) {
      streams.err << "\rrecording " << std::fixed << std::setprecision(1) << elapsed << " / " << options.duration_s
                  << " s, " << samples << " samples" << std::flush;
    } else if (static_cast<int>(elapsed) != last_second) {
      last_second = static_cast<int>(elapsed);
    }
  }
  (void)master.stop_daq();
  (void)master.disconnect();
  if (terminal) streams.err << '\n';
  streams.err << "recorded " << samples << " samples of " << recorded.size() << " signals on event '" << options.event
              << "' (" << master.overload_events() << " overloads, " << master.channel().counter_gaps()
              << " lost packets)\n";
  return ExitCode::success;
}

ExitCode run_checksum(const XcpOptions& options, Streams streams) {
  auto address = parse_number(options.address);
  if (!address) return report({address.error()}, streams);
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  auto checksum = session.value().master->checksum(0, address.value(), options.size);
  if (!checksum) return report({checksum.error()}, streams);
  (void)session.value().master->disconnect();
  char text[16];
  std::snprintf(text, sizeof(text), "0x%08X", checksum.value());
  if (options.json) {
    streams.out << json{{"address", address.value()}, {"size", options.size}, {"checksum", checksum.value()}}.dump(2)
                << '\n';
  } else {
    streams.out << text << '\n';
  }
  return ExitCode::success;
}

ExitCode run_page(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  const auto segment = static_cast<std::uint8_t>(options.segment);
  if (options.page >= 0) {
    std::uint8_t mode = 0;
    if (options.ecu || !options.xcp) mode |= 0x01;
    if (options.xcp || !options.ecu) mode |= 0x02;
    if (Status set = master.set_calibration_page(mode, segment, static_cast<std::uint8_t>(options.page)); !set) {
      return report({set.error()}, streams);
    }
  }
  auto ecu = master.calibration_page(0x01, segment);
  auto xcp_page = master.calibration_page(0x02, segment);
  if (!ecu) return report({ecu.error()}, streams);
  if (!xcp_page) return report({xcp_page.error()}, streams);
  (void)master.disconnect();
  if (options.json) {
    streams.out << json{{"segment", segment}, {"ecu_page", ecu.value()}, {"xcp_page", xcp_page.value()}}.dump(2)
                << '\n';
  } else {
    streams.out << "segment " << options.segment << ": ECU page " << ecu.value() + 0 << ", XCP page "
                << xcp_page.value() + 0 << " (0 working, 1 reference)\n";
  }
  return ExitCode::success;
}

}  // namespace

Action define_xcp_command(CLI::App& command) {
  auto options = std::make_shared<XcpOptions>();
  command.require_subcommand(1);
  auto add_connection = [&](CLI::App* action) {
    action->add_option("--connect", options->connect,
                       "The slave: tcp://host:port or udp://host:port (default: the A2L's)");
    action->add_option("--a2l", options->a2l_file, "The slave's A2L file: names, addresses, events, transport");
    action->add_option("--timeout", options->timeout_ms, "Milliseconds to wait for each response")
        ->check(CLI::PositiveNumber);
    action->add_flag("--json", options->json, "Print JSON for scripts");
  };
  add_connection(command.add_subcommand("info", "Connect and show what the slave offers"));
  CLI::App* list = command.add_subcommand("list", "List the A2L's signals and parameters");
  list->add_option("--a2l", options->a2l_file, "The A2L file")->required();
  list->add_flag("--json", options->json, "Print JSON for scripts");
  CLI::App* read = command.add_subcommand("read", "Read signals or parameters by name, or bytes as ADDRESS:SIZE");
  add_connection(read);
  read->add_option("targets", options->targets, "Names from the A2L, or ADDRESS:SIZE")->required();
  CLI::App* write = command.add_subcommand("write", "Write parameters: NAME=VALUE (physical value, within its limits)");
  add_connection(write);
  write->add_option("assignments", options->targets, "NAME=VALUE ...")->required();
  CLI::App* record = command.add_subcommand("record", "Record signals with DAQ to CSV");
  add_connection(record);
  record->add_option("--signal", options->signals, "A signal to record (repeat for more)")->required();
  record->add_option("--event", options->event, "The event (name or number) that samples them")->required();
  record->add_option("--duration", options->duration_s, "Seconds to record")->check(CLI::PositiveNumber);
  record->add_option("--output", options->output, "The CSV file (default: standard output)");
  CLI::App* checksum = command.add_subcommand("checksum", "BUILD_CHECKSUM over a block of the slave's memory");
  add_connection(checksum);
  checksum->add_option("address", options->address, "Start address (decimal or 0x hex)")->required();
  checksum->add_option("size", options->size, "Bytes")->required()->check(CLI::PositiveNumber);
  CLI::App* page =
      command.add_subcommand("page", "Show or switch a calibration segment's page (0 working, 1 reference)");
  add_connection(page);
  page->add_option("--segment", options->segment, "The segment number")->check(CLI::Range(0, 255));
  page->add_option("--page", options->page, "Switch to this page")->check(CLI::Range(0, 1));
  page->add_flag("--ecu", options->ecu, "Switch only what the model reads");
  page->add_flag("--xcp", options->xcp, "Switch only what XCP reads and writes");

  return [options, &command](Streams streams) {
    const CLI::App* chosen = command.get_subcommands().front();
    const std::string action = chosen->get_name();
    if (action == "info") return run_info(*options, streams);
    if (action == "list") return run_list(*options, streams);
    if (action == "read") return run_read(*options, streams);
    if (action == "write") return run_write(*options, streams);
    if (action == "record") return run_record(*options, streams);
    if (action == "checksum") return run_checksum(*options, streams);
    return run_page(*options, streams);
  };
}

}  // namespace duet::cli
