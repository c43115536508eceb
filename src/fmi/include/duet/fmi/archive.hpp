#pragma once
// An FMU's zip archive, opened with the checks that keep a hostile archive from writing outside its folder or
// filling the disk, and unpacked into a private folder (docs/FMI.md, "The archive").

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/support/temporary_folder.hpp"

struct zip;  // libzip's archive, kept out of duet's headers

namespace duet::fmi {

// The largest entry duet unpacks; FMUs are models and their libraries, far below this, and a zip bomb is refused
// before a byte is written.
inline constexpr std::uint64_t max_entry_bytes = std::uint64_t{512} << 20;

struct ArchiveEntry {
  std::string name;    // as in the archive: relative, '/'-separated; a folder's ends in '/'
  std::uint64_t size;  // unpacked
};

class Archive {
 public:
  // Opens `file` and checks every entry; one refused entry refuses the archive, with a message naming both.
  [[nodiscard]] static Result<Archive> open(const std::filesystem::path& file);

  [[nodiscard]] const std::vector<ArchiveEntry>& entries() const { return entries_; }
  [[nodiscard]] bool contains(std::string_view name) const;
  // One entry's bytes, e.g. modelDescription.xml.
  [[nodiscard]] Result<std::string> read(std::string_view name) const;
  // Every entry unpacked into a new private folder that is removed when the result goes.
  [[nodiscard]] Result<TemporaryFolder> extract() const;

 private:
  struct CloseZip {
    void operator()(zip* archive) const;
  };
  Archive(std::filesystem::path file, std::unique_ptr<zip, CloseZip> archive, std::vector<ArchiveEntry> entries)
      : file_(std::move(file)), zip_(std::move(archive)), entries_(std::move(entries)) {}

  std::filesystem::path file_;
  std::unique_ptr<zip, CloseZip> zip_;
  std::vector<ArchiveEntry> entries_;
};

}  // namespace duet::fmi
