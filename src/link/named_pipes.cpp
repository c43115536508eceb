#include "duet/link/named_pipes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>

namespace duet::link {
namespace {

constexpr const char* to_plant_name = "to_plant";
constexpr const char* from_plant_name = "from_plant";

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace

Result<NamedPipes> NamedPipes::create(const std::filesystem::path& folder) {
  for (const char* name : {to_plant_name, from_plant_name}) {
    const std::filesystem::path path = folder / name;
    if (::mkfifo(path.c_str(), 0600) != 0) return Failure{system_error("cannot make the pipe " + path.string())};
  }
  NamedPipes pipes{folder};
  // Reading end first, without waiting for a writer: the firmware's open for writing then does not wait either.
  pipes.to_plant_ = ::open((folder / to_plant_name).c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (pipes.to_plant_ < 0) return Failure{system_error("cannot open the pipe " + (folder / to_plant_name).string())};
  return pipes;
}

NamedPipes::NamedPipes(NamedPipes&& other) noexcept
    : folder_(std::move(other.folder_)), to_plant_(std::exchange(other.to_plant_, -1)) {}

NamedPipes::~NamedPipes() {
  if (to_plant_ >= 0) ::close(to_plant_);
  if (folder_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove(folder_ / to_plant_name, ignored);
  std::filesystem::remove(folder_ / from_plant_name, ignored);
}

// from_plant opens for writing only once the firmware has it open for reading (ENXIO until then): that is the
// connection. Polled every millisecond: it happens once per run.
Result<std::unique_ptr<FdStream>> NamedPipes::accept(Timeout timeout, Timeout stream_timeout) {
  if (to_plant_ < 0) return Failure{"the pipes to and from the plant are already in use"};
  const auto started = std::chrono::steady_clock::now();
  const std::filesystem::path from_plant = folder_ / from_plant_name;
  for (;;) {
    const int writing = ::open(from_plant.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (writing >= 0) {
      for (const int fd : {to_plant_, writing}) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return std::make_unique<FdStream>(std::exchange(to_plant_, -1), writing, stream_timeout);
    }
    if (errno != ENXIO) return Failure{system_error("cannot open the pipe " + from_plant.string())};
    if (timeout != no_timeout && std::chrono::steady_clock::now() - started >= timeout) {
      return Failure{"the firmware did not open the pipes in " + folder_.string()};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds{1});
  }
}

}  // namespace duet::link
