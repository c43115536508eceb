#pragma once
// For the robot's in-the-loop tests (sil_test.cpp, pil_test.cpp): programs run as child processes, as a user runs
// them, temporary files, and reading numbers out of what the programs print.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "duet/link/stream.hpp"
#include "duet/support/text_file.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace duet::sil {

using namespace std::chrono_literals;

// A file in the temporary folder, removed at the end of the test.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("balbot_test_" + std::to_string(::getpid()) + "_" + name)) {}
  ~TemporaryFile() { std::filesystem::remove(path_); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// A program running as a child process: its standard output on a pipe (read line by line while it runs), its
// standard error in a file (read once it is done, so that a long report cannot block it).
class Program {
 public:
  Program(const std::string& program, const std::vector<std::string>& arguments, const std::string& name)
      : errors_{name + ".err"} {
    int out[2] = {-1, -1};
    if (::pipe2(out, O_CLOEXEC) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors_.path().c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    std::vector<std::string> words{program};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    argv.reserve(words.size() + 1);
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    output_ = std::make_unique<link::FdStream>(out[0], out[0], 60s);
  }
  // A program still running when a test gives up (a server waiting for a firmware that failed) is stopped.
  ~Program() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      (void)wait();
    }
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  [[nodiscard]] bool started() const { return pid_ > 0; }
  // The next line of its standard output, without the newline ("" at its end).
  std::string line() {
    std::string text;
    std::uint8_t byte = 0;
    while (output_->read_exactly({&byte, 1}).ok() && byte != '\n') text += static_cast<char>(byte);
    return text;
  }
  // Waits for it to end: its exit code (128 + the signal when a signal ended it).
  int wait() {
    int status = 0;
    ::waitpid(std::exchange(pid_, -1), &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  // Its standard error: call after wait().
  [[nodiscard]] std::string errors() const {
    auto text = read_text_file(errors_.path());
    return text ? text.value() : "";
  }

 private:
  TemporaryFile errors_;
  pid_t pid_ = -1;
  std::unique_ptr<link::FdStream> output_;
};

// The number after `label` in a program's line ("...; final theta 0.0123 deg; ..."), exactly as written.
inline double number_after(const std::string& line, const std::string& label) {
  const std::size_t at = line.find(label);
  EXPECT_NE(at, std::string::npos) << label << " in: " << line;
  return at == std::string::npos ? NAN : std::strtod(line.c_str() + at + label.size(), nullptr);
}

// Where `duet plant serve` says it listens ("plant balbot listening on 127.0.0.1:40312"): its first line. The
// second, read too, says where it takes disturbances ("plant balbot control on ...").
inline std::string listening_address(Program& server) {
  const std::string line = server.line();
  const std::string prefix = "plant balbot listening on ";
  EXPECT_TRUE(line.starts_with(prefix)) << line;
  EXPECT_TRUE(server.line().starts_with("plant balbot control on "));
  return line.starts_with(prefix) ? line.substr(prefix.size()) : std::string{};
}

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace duet::sil
