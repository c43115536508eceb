// The FMU archive: what it lists, reads and unpacks, what it refuses and how it says so, and the writer.
#include "duet/fmi/archive.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "duet/fmi/archive_writer.hpp"
#include "testing/hand_made_zip.hpp"

namespace duet::fmi {
namespace {

using testing::hand_made_zip;
using testing::HandMadeEntry;

class ArchiveTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& bytes) const {
    const std::filesystem::path file = folder.path() / "test.fmu";
    std::ofstream{file, std::ios::binary} << bytes;
    return file;
  }
  std::string refusal(const std::vector<HandMadeEntry>& entries) const {
    const std::filesystem::path file = write(hand_made_zip(entries));
    auto archive = Archive::open(file);
    EXPECT_FALSE(archive);
    if (archive) return "";
    const std::string prefix = file.string() + ": ";
    EXPECT_EQ(archive.error().rfind(prefix, 0), 0u) << archive.error();
    return archive.error().substr(prefix.size());
  }
  TemporaryFolder folder = TemporaryFolder::make("duet-archive-test-").value();
};

std::string read_file(const std::filesystem::path& path) {
  std::ostringstream text;
  text << std::ifstream{path, std::ios::binary}.rdbuf();
  return text.str();
}

TEST_F(ArchiveTest, ListsReadsAndUnpacksEntries) {
  const auto file = write(hand_made_zip({{.name = "modelDescription.xml", .bytes = "<xml/>"},
                                         {.name = "binaries/", .bytes = "", .unix_mode = 040755},
                                         {.name = "binaries/x86_64-linux/Lag.so", .bytes = "ELF"}}));
  auto archive = Archive::open(file);
  ASSERT_TRUE(archive) << archive.error();
  ASSERT_EQ(archive.value().entries().size(), 3u);
  EXPECT_EQ(archive.value().entries()[2].name, "binaries/x86_64-linux/Lag.so");
  EXPECT_EQ(archive.value().entries()[2].size, 3u);
  EXPECT_TRUE(archive.value().contains("modelDescription.xml"));
  EXPECT_FALSE(archive.value().contains("resources/"));
  EXPECT_EQ(archive.value().read("modelDescription.xml").value(), "<xml/>");
  EXPECT_EQ(archive.value().read("nothing").error(), file.string() + ": no entry \"nothing\"");

  std::filesystem::path unpacked;
  {
    auto extracted = archive.value().extract();
    ASSERT_TRUE(extracted) << extracted.error();
    unpacked = extracted.value().path();
    struct stat status {};
    ASSERT_EQ(::stat(unpacked.c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 0777, 0700u);  // private: nobody else reads or plants files there
    EXPECT_EQ(read_file(unpacked / "binaries/x86_64-linux/Lag.so"), "ELF");
    EXPECT_EQ(read_file(unpacked / "modelDescription.xml"), "<xml/>");
  }
  EXPECT_FALSE(std::filesystem::exists(unpacked));  // removed with the object
}

TEST_F(ArchiveTest, RefusesWhatIsNotAZipArchive) {
  const auto file = write("<fmiModelDescription/> is not a zip archive at all, though it is long enough");
  EXPECT_EQ(Archive::open(file).error(), file.string() + ": not a zip archive");
  EXPECT_EQ(Archive::open("/nonexistent.fmu").error(), "/nonexistent.fmu: cannot open: No such file or directory");
}

TEST_F(ArchiveTest, RefusesUnsafeNames) {
  EXPECT_EQ(refusal({{.name = "/etc/passwd", .bytes = "x"}}), "entry \"/etc/passwd\": absolute path");
  EXPECT_EQ(refusal({{.name = "../evil", .bytes = "x"}}),
            "entry \"../evil\": '..' in the path (it would leave the folder it is unpacked into)");
  EXPECT_EQ(refusal({{.name = "binaries/../../evil", .bytes = "x"}}),
            "entry \"binaries/../../evil\": '..' in the path (it would leave the folder it is unpacked into)");
  EXPECT_EQ(refusal({{.name = "binaries\\win64\\Lag.dll", .bytes = "x"}}),
            "entry \"binaries\\win64\\Lag.dll\": backslash in the name (FMUs separate folders with '/')");
  EXPECT_EQ(refusal({{.name = "a//b", .bytes = "x"}}), "entry \"a//b\": empty or '.' component in the path");
}

TEST_F(ArchiveTest, RefusesLinksEncryptionForeignMethodsDuplicatesAndHugeEntries) {
  EXPECT_EQ(refusal({{.name = "link", .bytes = "/etc/passwd", .unix_mode = 0120777}}), "entry \"link\": symbolic link");
  EXPECT_EQ(refusal({{.name = "secret", .bytes = "x", .flags = 1}}), "entry \"secret\": encrypted");
  EXPECT_EQ(refusal({{.name = "packed", .bytes = "x", .method = 12}}),
            "entry \"packed\": compression method 12 (FMUs use only store and deflate)");
  EXPECT_EQ(refusal({{.name = "model.xml", .bytes = "a"}, {.name = "model.xml", .bytes = "b"}}),
            "entry \"model.xml\": appears twice");
  EXPECT_EQ(refusal({{.name = "bomb", .bytes = "x", .claimed_size = 0xFFFFFFF0u}}),
            "entry \"bomb\": 4294967280 bytes, more than the 536870912 duet unpacks from one entry");
}

TEST_F(ArchiveTest, RefusesAnEntryHoldingMoreThanItsHeaderDeclares) {
  const auto file = write(hand_made_zip({{.name = "liar", .bytes = "twelve bytes", .claimed_size = 3}}));
  auto archive = Archive::open(file);
  ASSERT_TRUE(archive) << archive.error();
  const auto read = archive.value().read("liar");
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error().rfind(file.string() + ": entry \"liar\": ", 0), 0u) << read.error();
}

TEST_F(ArchiveTest, WriterDeflatesAndTheReaderReadsItBack) {
  const std::filesystem::path library = folder.path() / "library.so";
  std::ofstream{library, std::ios::binary} << std::string(10000, 'z');
  const std::filesystem::path file = folder.path() / "written.fmu";
  const std::vector<ArchiveInput> inputs = {{"modelDescription.xml", std::string{"<fmiModelDescription/>"}},
                                            {"binaries/x86_64-linux/Lag.so", library}};
  ASSERT_TRUE(write_archive(file, inputs));
  EXPECT_LT(std::filesystem::file_size(file), 1000u);  // deflated, not stored
  auto archive = Archive::open(file);
  ASSERT_TRUE(archive) << archive.error();
  EXPECT_EQ(archive.value().read("modelDescription.xml").value(), "<fmiModelDescription/>");
  EXPECT_EQ(archive.value().read("binaries/x86_64-linux/Lag.so").value(), std::string(10000, 'z'));
}

TEST_F(ArchiveTest, WriterRefusesWhatTheReaderWouldAndLeavesNothing) {
  const std::filesystem::path file = folder.path() / "refused.fmu";
  const std::vector<ArchiveInput> traversal = {{"../evil", std::string{"x"}}};
  EXPECT_EQ(write_archive(file, traversal).error(),
            file.string() + ": entry \"../evil\": '..' in the path (it would leave the folder it is unpacked into)");
  const std::vector<ArchiveInput> twice = {{"a", std::string{"x"}}, {"a", std::string{"y"}}};
  EXPECT_EQ(write_archive(file, twice).error(), file.string() + ": entry \"a\": appears twice");
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace duet::fmi
