// Where src/mdf4 is not built (the board's bridge, a7-linux): no MDF4 files, and no `mdf4` in the description, so
// that the page hides its "Save as MDF4" buttons; the paths are the front end's files (none such: 404).
#include "duet/dashboard/dashboard.hpp"

namespace duet::dashboard {

nlohmann::json Dashboard::mdf4_offer() const { return nullptr; }

std::optional<HttpAnswer> Dashboard::answer_http(const HttpRequest&) const { return std::nullopt; }

}  // namespace duet::dashboard
