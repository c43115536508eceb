#pragma once
// The plant's end of a link through two named pipes (mkfifo) in a folder, `to_plant` and `from_plant`: how the
// firmware on QEMU's emulated Cortex-M4 reaches its plant (by semihosting, ports/mps2-an386/plant_link.hpp), since
// a pipe moves a whole frame per system call where QEMU's UART moves a byte per turn of its main loop.
//
// The firmware opens to_plant for writing, then from_plant for reading. The plant opens to_plant for reading at
// once (without waiting for a writer), and from_plant for writing as soon as the firmware waits to read it; from
// then on the pipes are a stream like a socket: the firmware's end (QEMU exiting) is the end of to_plant.

#include <filesystem>
#include <memory>

#include "duet/link/stream.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

class NamedPipes {
 public:
  // Makes the two pipes in `folder` (which must exist).
  [[nodiscard]] static Result<NamedPipes> create(const std::filesystem::path& folder);
  NamedPipes(NamedPipes&& other) noexcept;
  NamedPipes& operator=(NamedPipes&&) = delete;
  NamedPipes(const NamedPipes&) = delete;
  NamedPipes& operator=(const NamedPipes&) = delete;
  // Closes what is open and removes the pipes.
  ~NamedPipes();

  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }

  // Waits up to `timeout` for the firmware to open its ends; the stream then has `stream_timeout` for its reads
  // and writes. Call again after a timeout; once a stream has been returned, the pipes are its.
  [[nodiscard]] Result<std::unique_ptr<FdStream>> accept(Timeout timeout, Timeout stream_timeout = default_timeout);

 private:
  explicit NamedPipes(std::filesystem::path folder) : folder_(std::move(folder)) {}

  std::filesystem::path folder_;
  int to_plant_ = -1;  // the plant reads it
};

}  // namespace duet::link
