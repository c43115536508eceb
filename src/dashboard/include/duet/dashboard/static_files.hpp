#pragma once
// Which file of the front end's folder an HTTP request's target names, and its content type. Only plain names
// under the folder are served: no "..", no hidden files, no percent-escapes, so a request reaches nothing else.

#include <filesystem>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::dashboard {

// "/" is index.html; a query ("?ws=...") is ignored. Fails (to be answered 404) for names outside the rules or
// files that are not there.
Result<std::filesystem::path> file_for(const std::filesystem::path& root, std::string_view target);
std::string_view content_type(const std::filesystem::path& file);

// Where the built front end is: share/duet/web beside the program's folder (an installation, the board), else the
// source tree's web/dist that this build was configured from, else empty.
std::filesystem::path default_web_root();

}  // namespace duet::dashboard
