#pragma once
// A private folder (mkdtemp: mode 0700, a name nobody else has) for a run's sockets and files, removed with its
// contents when it goes.

#include <filesystem>
#include <string_view>
#include <utility>

#include "duet/support/result.hpp"

namespace duet {

class TemporaryFolder {
 public:
  // Under the system's temporary folder ($TMPDIR or /tmp), named `prefix` and six random characters.
  [[nodiscard]] static Result<TemporaryFolder> make(std::string_view prefix);
  TemporaryFolder(TemporaryFolder&& other) noexcept : path_(std::exchange(other.path_, {})) {}
  TemporaryFolder& operator=(TemporaryFolder&&) = delete;
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder();

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  explicit TemporaryFolder(std::filesystem::path path) : path_(std::move(path)) {}
  std::filesystem::path path_;
};

}  // namespace duet
