#include "xcp_session.hpp"

#include <chrono>
#include <stdexcept>

#include "duet/support/text_file.hpp"
#include "duet/xcp/host/epk.hpp"
#include "duet/xcp/host/values.hpp"

namespace duet::cli::xcp_actions {
namespace {

using namespace duet::xcp::host;

Result<A2lDescription> load_a2l(const std::string& file) {
  auto text = read_text_file(file);
  if (!text) return Failure{text.error()};
  return read_a2l(text.value(), file);
}

const Variable* find_variable(const A2lDescription& a2l, const std::string& name) {
  for (const auto* list : {&a2l.measurements, &a2l.characteristics}) {
    for (const Variable& variable : *list) {
      if (variable.name == name) return &variable;
    }
  }
  return nullptr;
}

}  // namespace

Result<Session> open_session(const XcpOptions& options, bool needs_master, std::ostream& warnings) {
  Session session;
  if (!options.a2l_file.empty()) {
    auto a2l = load_a2l(options.a2l_file);
    if (!a2l) return Failure{a2l.error()};
    session.a2l = std::move(a2l).value();
    for (const std::string& warning : session.a2l->warnings) warnings << "duet xcp: warning: " << warning << '\n';
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
  if (Status connected = connect_master(session, endpoint, std::chrono::milliseconds{options.timeout_ms}); !connected) {
    return Failure{connected.error()};
  }
  return session;
}

Status connect_master(Session& session, const Endpoint& slave, std::chrono::milliseconds timeout) {
  auto channel = MasterChannel::open(slave, timeout);
  if (!channel) return Failure{channel.error()};
  session.master = std::make_unique<Master>(std::move(channel).value(), timeout);
  session.slave = slave;
  if (auto connected = session.master->connect(); !connected) return Failure{connected.error()};
  if (session.a2l) {
    if (Status same = check_epk(*session.master, *session.a2l); !same) return Failure{same.error()};
  }
  return done();
}

Result<const Variable*> variable_named(const Session& session, const std::string& name) {
  if (!session.a2l) return Failure{"'" + name + "': names need --a2l FILE"};
  const Variable* variable = find_variable(*session.a2l, name);
  if (variable == nullptr) return Failure{"'" + name + "' is neither a MEASUREMENT nor a CHARACTERISTIC in the A2L"};
  return variable;
}

Result<ParameterWrite> parse_assignment(const Session& session, const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos) return Failure{"'" + assignment + "': expected NAME=VALUE"};
  auto variable = variable_named(session, assignment.substr(0, equals));
  if (!variable) return Failure{variable.error()};
  double value = 0;
  try {
    std::size_t used = 0;
    value = std::stod(assignment.substr(equals + 1), &used);
    if (used != assignment.size() - equals - 1) throw std::invalid_argument{assignment};
  } catch (const std::exception&) {
    return Failure{"'" + assignment + "': the value is not a number"};
  }
  auto element = encode(*variable.value(), value);
  if (!element) return Failure{element.error()};
  ParameterWrite write{assignment, variable.value(), {}};
  for (std::uint32_t index = 0; index < write.variable->count; ++index)
    write.bytes.insert(write.bytes.end(), element.value().begin(), element.value().end());
  return write;
}

Status apply(Master& master, const ParameterWrite& write) {
  return master.download(write.variable->extension, write.variable->address, write.bytes);
}

ExitCode report(const Failure& failure, Streams streams) {
  streams.err << "duet xcp: " << failure.message << '\n';
  return ExitCode::failure;
}

}  // namespace duet::cli::xcp_actions
