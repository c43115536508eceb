#include "duet/fmi/archive_writer.hpp"

#include <zip.h>

#include <set>

#include "entry_name.hpp"

namespace duet::fmi {
namespace {

zip_source_t* source_of(zip_t* archive, const std::variant<std::string, std::filesystem::path>& content) {
  if (const auto* bytes = std::get_if<std::string>(&content))
    return zip_source_buffer(archive, bytes->data(), bytes->size(), 0);  // `inputs` outlives zip_close
  return zip_source_file(archive, std::get<std::filesystem::path>(content).c_str(), 0, -1);  // -1: to the end
}

}  // namespace

Status write_archive(const std::filesystem::path& file, std::span<const ArchiveInput> inputs) {
  int code = 0;
  zip_t* archive = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
  if (archive == nullptr) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    std::string text = file.string() + ": cannot create: " + zip_error_strerror(&error);
    zip_error_fini(&error);
    return Failure{text};
  }
  std::set<std::string, std::less<>> names;
  for (const ArchiveInput& input : inputs) {
    std::string problem;
    if (auto name_problem = entry_name_problem(input.name))
      problem = *name_problem;
    else if (!names.insert(input.name).second)
      problem = "appears twice";
    zip_source_t* source = problem.empty() ? source_of(archive, input.content) : nullptr;
    zip_int64_t index = -1;
    if (source != nullptr) {
      index = zip_file_add(archive, input.name.c_str(), source, ZIP_FL_ENC_UTF_8);
      if (index < 0) zip_source_free(source);  // not taken over by the archive
    }
    if (problem.empty() &&
        (index < 0 || zip_set_file_compression(archive, static_cast<zip_uint64_t>(index), ZIP_CM_DEFLATE, 0) != 0))
      problem = zip_strerror(archive);
    if (!problem.empty()) {
      zip_discard(archive);
      return Failure{file.string() + ": entry \"" + input.name + "\": " + problem};
    }
  }
  if (zip_close(archive) != 0) {
    std::string text = file.string() + ": cannot write: " + zip_strerror(archive);
    zip_discard(archive);
    return Failure{text};
  }
  return done();
}

}  // namespace duet::fmi
