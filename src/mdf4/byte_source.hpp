#pragma once
// The bytes of an MDF file, read at any offset without loading the file: from disk (pread) or from memory.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::mdf4 {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  [[nodiscard]] virtual std::uint64_t size() const = 0;
  // Precondition: offset + count <= size(). Returns false only if the read itself fails.
  virtual bool read(std::uint64_t offset, std::uint8_t* into, std::size_t count) const = 0;
  [[nodiscard]] virtual const std::string& name() const = 0;
};

Result<std::unique_ptr<ByteSource>> open_file_source(const std::filesystem::path& path);
std::unique_ptr<ByteSource> memory_source(std::vector<std::uint8_t> bytes, std::string name);

}  // namespace duet::mdf4
