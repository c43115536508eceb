#include "duet/support/compiler.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include "duet/support/text_file.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX declares it nowhere in C++ headers

namespace duet {

std::string cxx_compiler() {
  const char* compiler = std::getenv("CXX");
  return compiler != nullptr && *compiler != '\0' ? compiler : "c++";
}

Status compile(std::vector<std::string> command, const std::filesystem::path& messages, std::string_view what) {
  std::vector<char*> argv;
  for (std::string& argument : command) argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, messages.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  pid_t child = 0;
  const int spawned = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return Failure{"the C++ compiler '" + command[0] + "' was not found (set CXX)"};
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const auto text = read_text_file(messages.string());
    return Failure{std::string{what} + " did not compile:\n" + (text.ok() ? text.value() : std::string{})};
  }
  return done();
}

}  // namespace duet
