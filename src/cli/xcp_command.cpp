#include "xcp_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/values.hpp"
#include "duet/xcp/protocol.hpp"
#include "xcp_record.hpp"
#include "xcp_session.hpp"

namespace duet::cli {
namespace {

using nlohmann::json;
using namespace duet::xcp::host;
using namespace xcp_actions;

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
  std::ostringstream out;
  for (std::size_t index = 0; index < bytes.size(); ++index) {
    out << (index == 0 ? "" : " ") << std::hex << std::uppercase << std::setw(2) << std::setfill('0')
        << static_cast<unsigned>(bytes[index]);
  }
  return out.str();
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

// How the slave builds DAQ packets, for people: "relative ODT number, DAQ list word; 4-byte timestamps of 1e-06 s".
std::string daq_layout(const DaqProcessor& daq) {
  constexpr std::array identification{"absolute ODT number", "relative ODT number, DAQ list byte",
                                      "relative ODT number, DAQ list word",
                                      "relative ODT number, fill byte, DAQ list word"};
  std::ostringstream text;
  text << identification[static_cast<std::size_t>(daq.identification)] << "; ";
  if (daq.timestamps()) {
    text << static_cast<unsigned>(daq.timestamp_size) << "-byte timestamps of " << daq.seconds_per_tick() << " s";
  } else {
    text << "no timestamps";
  }
  return text.str();
}

ExitCode run_info(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true, streams.err);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  const SlaveProperties& slave = master.properties();
  auto id = master.identification(1);
  const std::string name = id ? std::string(id.value().begin(), id.value().end()) : std::string{};
  const std::optional<DaqProcessor>& daq = master.daq_processor();
  json info{{"identification", name},
            {"max_cto", slave.max_cto},
            {"max_dto", slave.max_dto},
            {"protocol_version", slave.protocol_version},
            {"transport_version", slave.transport_version},
            {"byte_order", slave.byte_order == xcp::ByteOrder::intel ? "intel" : "motorola"},
            {"calibration_paging", (slave.resources & xcp::resource::calibration_paging) != 0},
            {"daq", (slave.resources & xcp::resource::daq) != 0}};
  if (daq) info["daq_layout"] = daq_layout(*daq);
  const Status disconnected = master.disconnect();
  if (options.json) {
    streams.out << info.dump(2) << '\n';
  } else {
    streams.out << "slave        " << name << "\nMAX_CTO      " << slave.max_cto + 0 << "\nMAX_DTO      "
                << slave.max_dto << "\nprotocol     " << slave.protocol_version + 0 << ", transport "
                << slave.transport_version + 0 << "\nbyte order   "
                << (slave.byte_order == xcp::ByteOrder::intel ? "Intel" : "Motorola") << "\nresources    "
                << (info["calibration_paging"] ? "calibration/paging " : "") << (info["daq"] ? "DAQ" : "") << '\n';
    if (daq) streams.out << "DAQ packets  " << daq_layout(*daq) << '\n';
  }
  // What was learnt is shown; an error answer still fails the command.
  if (!id) return report({id.error()}, streams);
  if (!disconnected) return report({disconnected.error()}, streams);
  return ExitCode::success;
}

ExitCode run_list(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, false, streams.err);
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
  auto session = open_session(options, true, streams.err);
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
  if (Status disconnected = master.disconnect(); !disconnected) return report({disconnected.error()}, streams);
  if (options.json) {
    streams.out << values.dump(2) << '\n';
  } else {
    for (const auto& [name, value] : values.items()) streams.out << name << " = " << value.dump() << '\n';
  }
  return ExitCode::success;
}

ExitCode run_write(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true, streams.err);
  if (!session) return report({session.error()}, streams);
  Master& master = *session.value().master;
  for (const std::string& assignment : options.targets) {
    auto write = parse_assignment(session.value(), assignment);
    if (!write) return report({write.error()}, streams);
    if (Status written = apply(master, write.value()); !written) return report({written.error()}, streams);
  }
  if (Status disconnected = master.disconnect(); !disconnected) return report({disconnected.error()}, streams);
  return ExitCode::success;
}

ExitCode run_checksum(const XcpOptions& options, Streams streams) {
  auto address = parse_number(options.address);
  if (!address) return report({address.error()}, streams);
  auto session = open_session(options, true, streams.err);
  if (!session) return report({session.error()}, streams);
  auto checksum = session.value().master->checksum(0, address.value(), options.size);
  if (!checksum) return report({checksum.error()}, streams);
  if (Status disconnected = session.value().master->disconnect(); !disconnected) {
    return report({disconnected.error()}, streams);
  }
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
  auto session = open_session(options, true, streams.err);
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
  if (Status disconnected = master.disconnect(); !disconnected) return report({disconnected.error()}, streams);
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
  CLI::App* record = command.add_subcommand("record", "Record signals with DAQ to CSV and MDF 4");
  add_connection(record);
  record
      ->add_option("--signal", options->signals,
                   "A signal to record, NAME or NAME@EVENT (repeat for more; a list and a group per event)")
      ->required();
  record->add_option("--event", options->event, "The event (name or number) that samples signals without @EVENT");
  record->add_option("--duration", options->duration_s, "Seconds to record")->check(CLI::PositiveNumber);
  record->add_option("--output", options->output, "The CSV file (default: standard output, unless --mdf is given)");
  record->add_option("--plot", options->plot, "Also an SVG plot of the recording, a panel per unit");
  record->add_option("--mdf", options->mdf, "Also an MDF 4 file: a group per event, the signals in their A2L types");
  record->add_flag("--event-time", options->event_time,
                   "Time each sample by its number and the event's period in the A2L, not by the DAQ timestamp");
  record->add_option("--write-at", options->timed_writes,
                     "SECONDS:NAME=VALUE: write a parameter that long after the recording started (repeat for more)");
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
