#include "duet/xcp/host/epk.hpp"

#include <cstdio>
#include <string>

namespace duet::xcp::host {

Status check_epk(Master& master, const A2lDescription& a2l) {
  if (a2l.epk.empty()) return done();
  char address[16];
  std::snprintf(address, sizeof address, "0x%X", a2l.epk_address);
  auto uploaded = master.upload(0, a2l.epk_address, static_cast<std::uint32_t>(a2l.epk.size()));
  if (!uploaded) {
    return Failure{"the slave's EPK at " + std::string{address} + " cannot be read (" + uploaded.error() +
                   "): is the A2L this firmware's?"};
  }
  const std::string held(uploaded.value().begin(), uploaded.value().end());
  if (held != a2l.epk) {
    return Failure{"the slave holds EPK \"" + held + "\" at " + address + ", the A2L names \"" + a2l.epk +
                   "\": the A2L does not describe this firmware (generate it from the firmware's model, or load the "
                   "firmware it was generated with)"};
  }
  return done();
}

}  // namespace duet::xcp::host
