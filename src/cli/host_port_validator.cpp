#include "host_port_validator.hpp"

#include <string>

#include "duet/link/tcp.hpp"

namespace duet::cli {

CLI::Validator host_port_validator() {
  return CLI::Validator(
      [](const std::string& text) {
        auto parsed = link::parse_host_port(text);
        return parsed ? std::string{} : parsed.error();
      },
      "");
}

}  // namespace duet::cli
