// Packs the test FMUs at build time: fmu_pack [--hand-made] OUT.fmu NAME=FILE...
// Without --hand-made through duet's archive writer; with it byte by byte, for archives the writer refuses to make
// (a path-traversal entry).
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "duet/fmi/archive_writer.hpp"
#include "hand_made_zip.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> arguments(argv + 1, argv + argc);
  const bool hand_made = !arguments.empty() && arguments.front() == "--hand-made";
  if (hand_made) arguments.erase(arguments.begin());
  if (arguments.size() < 2) {
    std::cerr << "usage: fmu_pack [--hand-made] OUT.fmu NAME=FILE...\n";
    return 2;
  }
  std::vector<duet::fmi::ArchiveInput> inputs;
  std::vector<duet::fmi::testing::HandMadeEntry> entries;
  for (std::size_t index = 1; index < arguments.size(); ++index) {
    const std::size_t equals = arguments[index].find('=');
    if (equals == std::string::npos) {
      std::cerr << "fmu_pack: " << arguments[index] << ": not NAME=FILE\n";
      return 2;
    }
    const std::string name = arguments[index].substr(0, equals);
    const std::filesystem::path file = arguments[index].substr(equals + 1);
    std::ostringstream bytes;
    bytes << std::ifstream{file, std::ios::binary}.rdbuf();
    entries.push_back({.name = name, .bytes = bytes.str()});
    inputs.push_back({name, file});
  }
  if (hand_made) {
    std::ofstream{arguments.front(), std::ios::binary} << duet::fmi::testing::hand_made_zip(entries);
    return 0;
  }
  const duet::Status written = duet::fmi::write_archive(arguments.front(), inputs);
  if (!written) std::cerr << "fmu_pack: " << written.error() << '\n';
  return written ? 0 : 1;
}
