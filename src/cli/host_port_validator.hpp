#pragma once
// A CLI11 check for HOST:PORT options (duet::link::parse_host_port): the message quotes the text and says what is
// wrong with it.

#include <CLI/CLI.hpp>

namespace duet::cli {

[[nodiscard]] CLI::Validator host_port_validator();

}  // namespace duet::cli
