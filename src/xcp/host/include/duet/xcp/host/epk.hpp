#pragma once
// Whether a slave is the firmware an A2L describes, as CANape and INCA check at connect: the EPK the A2L names
// (MOD_PAR EPK) must be what the slave holds at ADDR_EPK. Addresses from another firmware's A2L would read the wrong
// signals and write parameters into the wrong memory.

#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"

namespace duet::xcp::host {

// Uploads the EPK from `a2l.epk_address` and compares; an A2L without an EPK cannot tell, and passes.
[[nodiscard]] Status check_epk(Master& master, const A2lDescription& a2l);

}  // namespace duet::xcp::host
