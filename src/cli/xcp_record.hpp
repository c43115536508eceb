#pragma once
// `duet xcp record`: signals sampled by DAQ on one event, written as CSV (and an SVG plot), with parameter writes at
// given times in the same session.

#include "subcommand.hpp"
#include "xcp_session.hpp"

namespace duet::cli::xcp_actions {

// Records for options.duration_s seconds of the PC's clock; blocks until then.
ExitCode run_record(const XcpOptions& options, Streams streams);

}  // namespace duet::cli::xcp_actions
