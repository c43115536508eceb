#pragma once
// An MDF 4 file's channels as CSV, as `duet mdf export` writes it: a time column, then one column per channel; the
// groups' records merged in time order, one row per distinct time, a field empty where its group has no sample at
// that time or the sample is invalid.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "duet/mdf4/reader.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4 {

struct CsvExport {
  std::uint64_t rows = 0;
  std::size_t columns = 0;               // besides the time
  std::vector<std::string> not_decoded;  // channels left out: duet does not decode their type
};

// `channels`: the names to export, in that order, each `NAME` or `GROUP:NAME` (GROUP the group's index, for a name
// several groups have); empty: every decoded channel but the masters. A group without a master is timed by its
// record index.
Result<CsvExport> export_csv(const Reader& reader, const std::vector<std::string>& channels, std::ostream& out);

}  // namespace duet::mdf4
