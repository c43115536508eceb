#include "duet/fmi/archive.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zip.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <set>

#include "entry_name.hpp"

namespace duet::fmi {
namespace {

std::string in_quotes(std::string_view name) { return '"' + std::string{name} + '"'; }

std::string open_problem(int code) {
  if (code == ZIP_ER_NOZIP) return "not a zip archive";
  if (code == ZIP_ER_NOENT) return "cannot open: No such file or directory";
  zip_error_t error;
  zip_error_init_with_code(&error, code);
  std::string text = std::string{"cannot open: "} + zip_error_strerror(&error);
  zip_error_fini(&error);
  return text;
}

// Why entry `index` may not be unpacked, or nothing.
std::optional<std::string> entry_problem(zip_t* archive, zip_uint64_t index, const zip_stat_t& stat) {
  if (auto problem = entry_name_problem(stat.name)) return problem;
  zip_uint8_t system = 0;
  zip_uint32_t attributes = 0;
  if (zip_file_get_external_attributes(archive, index, 0, &system, &attributes) == 0 && system == ZIP_OPSYS_UNIX) {
    const auto mode = static_cast<mode_t>(attributes >> 16);  // a Unix zip keeps st_mode in the high half
    if (S_ISLNK(mode)) return "symbolic link";
    if ((mode & S_IFMT) != 0 && !S_ISREG(mode) && !S_ISDIR(mode)) return "neither a file nor a folder";
  }
  if ((stat.valid & ZIP_STAT_ENCRYPTION_METHOD) != 0 && stat.encryption_method != ZIP_EM_NONE) return "encrypted";
  if ((stat.valid & ZIP_STAT_COMP_METHOD) != 0 && stat.comp_method != ZIP_CM_STORE &&
      stat.comp_method != ZIP_CM_DEFLATE)
    return "compression method " + std::to_string(stat.comp_method) + " (FMUs use only store and deflate)";
  if (stat.size > max_entry_bytes)
    return std::to_string(stat.size) + " bytes, more than the " + std::to_string(max_entry_bytes) +
           " duet unpacks from one entry";
  return std::nullopt;
}

// Reads entry `index` in pieces and hands them to `write`, never more than the `size` its header declared.
template <typename Write>
Status copy_entry(zip_t* archive, const std::string& where, zip_uint64_t index, std::uint64_t size,
                  const Write& write) {
  zip_file_t* file = zip_fopen_index(archive, index, 0);
  if (file == nullptr) return Failure{where + ": cannot read: " + zip_strerror(archive)};
  std::array<char, 65536> piece{};
  std::uint64_t total = 0;
  Status status = done();
  while (true) {
    const zip_int64_t count = zip_fread(file, piece.data(), piece.size());
    if (count < 0) {
      status = Failure{where + ": cannot read: " + zip_file_strerror(file)};
      break;
    }
    if (count == 0) break;
    total += static_cast<std::uint64_t>(count);
    if (total > size) {
      status = Failure{where + ": holds more than the " + std::to_string(size) + " bytes its header declares"};
      break;
    }
    if (!(status = write(std::string_view{piece.data(), static_cast<std::size_t>(count)}))) break;
  }
  zip_fclose(file);
  return status;
}

Status write_all(int descriptor, std::string_view bytes, const std::filesystem::path& path) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(descriptor, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return Failure{path.string() + ": cannot write: " + std::strerror(errno)};
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return done();
}

}  // namespace

void Archive::CloseZip::operator()(zip* archive) const { zip_discard(archive); }

Result<Archive> Archive::open(const std::filesystem::path& file) {
  int code = 0;
  zip_t* opened = zip_open(file.c_str(), ZIP_RDONLY, &code);
  if (opened == nullptr) return Failure{file.string() + ": " + open_problem(code)};
  std::unique_ptr<zip, CloseZip> archive{opened};
  const zip_int64_t count = zip_get_num_entries(opened, 0);
  std::vector<ArchiveEntry> entries;
  std::set<std::string, std::less<>> seen;
  for (zip_uint64_t index = 0; index < static_cast<zip_uint64_t>(count); ++index) {
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(opened, index, 0, &stat) != 0 || (stat.valid & ZIP_STAT_NAME) == 0)
      return Failure{file.string() + ": entry " + std::to_string(index) + ": " + zip_strerror(opened)};
    const std::string name = stat.name;
    if (auto problem = entry_problem(opened, index, stat))
      return Failure{file.string() + ": entry " + in_quotes(name) + ": " + *problem};
    std::string key = name;
    if (key.back() == '/') key.pop_back();  // "a" and "a/" would unpack to the same place
    if (!seen.insert(key).second) return Failure{file.string() + ": entry " + in_quotes(name) + ": appears twice"};
    entries.push_back({name, stat.size});
  }
  return Archive{file, std::move(archive), std::move(entries)};
}

bool Archive::contains(std::string_view name) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const ArchiveEntry& entry) { return entry.name == name; });
}

Result<std::string> Archive::read(std::string_view name) const {
  const auto entry =
      std::find_if(entries_.begin(), entries_.end(), [&](const ArchiveEntry& each) { return each.name == name; });
  if (entry == entries_.end()) return Failure{file_.string() + ": no entry " + in_quotes(name)};
  std::string bytes;
  bytes.reserve(entry->size);
  auto index = static_cast<zip_uint64_t>(entry - entries_.begin());
  Status read = copy_entry(zip_.get(), file_.string() + ": entry " + in_quotes(name), index, entry->size,
                           [&](std::string_view piece) {
                             bytes += piece;
                             return done();
                           });
  if (!read) return Failure{read.error()};
  return bytes;
}

Result<TemporaryFolder> Archive::extract() const {
  auto folder = TemporaryFolder::make("duet-fmu-");
  if (!folder) return Failure{file_.string() + ": " + folder.error()};
  for (std::size_t index = 0; index < entries_.size(); ++index) {
    const ArchiveEntry& entry = entries_[index];
    const std::filesystem::path target = folder.value().path() / entry.name;
    std::error_code error;
    std::filesystem::create_directories(entry.name.back() == '/' ? target : target.parent_path(), error);
    if (error) return Failure{target.string() + ": cannot make the folder: " + error.message()};
    if (entry.name.back() == '/') continue;
    // O_EXCL and O_NOFOLLOW: nothing already there (a link planted by an earlier entry) is written through.
    const int descriptor = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (descriptor < 0) return Failure{target.string() + ": cannot create: " + std::strerror(errno)};
    Status copied = copy_entry(zip_.get(), file_.string() + ": entry " + in_quotes(entry.name), index, entry.size,
                               [&](std::string_view piece) { return write_all(descriptor, piece, target); });
    if (::close(descriptor) != 0 && copied) copied = Failure{target.string() + ": " + std::strerror(errno)};
    if (!copied) return Failure{copied.error()};
  }
  return folder;
}

}  // namespace duet::fmi
