#include "duet/dashboard/static_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace duet::dashboard {
namespace {

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(root / "assets");
    std::ofstream{root / "index.html"} << "<!doctype html>";
    std::ofstream{root / "assets" / "app.js"} << "";
    std::ofstream{root / ".secret"} << "";
    std::ofstream{root.parent_path() / "outside.txt"} << "";
  }
  void TearDown() override { std::filesystem::remove_all(root.parent_path()); }

  std::filesystem::path root =
      std::filesystem::temp_directory_path() / ("duet-static-" + std::to_string(::getpid())) / "web";
};

TEST_F(StaticFiles, TheRootIsTheIndexAndQueriesAreIgnored) {
  EXPECT_EQ(file_for(root, "/").value(), root / "index.html");
  EXPECT_EQ(file_for(root, "/?ws=ws://127.0.0.1:1/").value(), root / "index.html");
  EXPECT_EQ(file_for(root, "/assets/app.js").value(), root / "assets" / "app.js");
}

TEST_F(StaticFiles, NothingOutsideTheFolderOrHiddenIsServed) {
  EXPECT_FALSE(file_for(root, "/../outside.txt").ok());
  EXPECT_FALSE(file_for(root, "/assets/../../outside.txt").ok());
  EXPECT_FALSE(file_for(root, "/%2e%2e/outside.txt").ok());
  EXPECT_FALSE(file_for(root, "/.secret").ok());
  EXPECT_FALSE(file_for(root, "//etc/passwd").ok());
  EXPECT_FALSE(file_for(root, "/missing.js").ok());
  EXPECT_FALSE(file_for(root, "/assets").ok());  // a folder is not a file
  EXPECT_FALSE(file_for(root, "index.html").ok());
}

TEST(ContentType, FollowsTheExtension) {
  EXPECT_EQ(content_type("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(content_type("app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(content_type("uPlot.min.css"), "text/css; charset=utf-8");
  EXPECT_EQ(content_type("blob"), "application/octet-stream");
}

}  // namespace
}  // namespace duet::dashboard
