#pragma once
// What the actions of `duet xcp` share (xcp_command.cpp, xcp_record.cpp): their options, a session with the slave
// (the A2L and a connected master), names looked up in the A2L, parameter writes checked before they are sent, and
// failures reported as "duet xcp: ...".

#include <chrono>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"
#include "subcommand.hpp"

namespace duet::cli::xcp_actions {

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
  std::string plot;
  std::string mdf;
  bool event_time = false;
  std::vector<std::string> timed_writes;  // SECONDS:NAME=VALUE
  std::string address;
  std::uint32_t size = 0;
  int segment = 0;
  int page = -1;
  bool ecu = false;
  bool xcp = false;
};

// Everything an action needs: the A2L (if given) and a connected master.
struct Session {
  std::optional<xcp::host::A2lDescription> a2l;
  std::unique_ptr<xcp::host::Master> master;
  xcp::host::Endpoint slave;  // where the master is connected
};

// Reads --a2l if given and, if `needs_master`, connects to --connect or else to the A2L's transport.
// What the A2L reader left out of the file is said on `warnings`, a line each.
[[nodiscard]] Result<Session> open_session(const XcpOptions& options, bool needs_master, std::ostream& warnings);

// Connects a master to `slave`, each command answered within `timeout`, and checks the slave's EPK against the
// session's A2L if it has one.
[[nodiscard]] Status connect_master(Session& session, const xcp::host::Endpoint& slave,
                                    std::chrono::milliseconds timeout);

// A MEASUREMENT or CHARACTERISTIC of the session's A2L by name.
[[nodiscard]] Result<const xcp::host::Variable*> variable_named(const Session& session, const std::string& name);

// A parameter write checked against the A2L (name, number, limits) before anything is sent: NAME=VALUE sets every
// element of NAME to VALUE.
struct ParameterWrite {
  std::string assignment;
  const xcp::host::Variable* variable = nullptr;
  std::vector<std::uint8_t> bytes;
};

[[nodiscard]] Result<ParameterWrite> parse_assignment(const Session& session, const std::string& assignment);
// Downloads the write's bytes to the slave (blocks until the slave answered).
[[nodiscard]] Status apply(xcp::host::Master& master, const ParameterWrite& write);

// Prints "duet xcp: MESSAGE" on standard error; returns ExitCode::failure.
ExitCode report(const Failure& failure, Streams streams);

}  // namespace duet::cli::xcp_actions
