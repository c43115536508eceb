#include "child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>
#include <utility>

namespace duet::cli {
namespace {

// The descriptors a start() opens, closed on every way out of it.
class Descriptors {
 public:
  Descriptors() = default;
  Descriptors(const Descriptors&) = delete;
  Descriptors& operator=(const Descriptors&) = delete;
  ~Descriptors() {
    for (const int fd : fds_) {
      if (fd >= 0) ::close(fd);
    }
  }
  // A descriptor to close at the end (returned as given).
  int keep(int fd) {
    fds_.push_back(fd);
    return fd;
  }
  // Takes one back, to outlive start().
  int release(int fd) {
    for (int& kept : fds_) {
      if (kept == fd) kept = -1;
    }
    return fd;
  }

 private:
  std::vector<int> fds_;
};

int exit_code_of(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

// In the child between fork and exec: only async-signal-safe calls. Reports errno on `report` if exec fails.
[[noreturn]] void become(char* const* argv, pid_t parent, int null_fd, int out_fd, int err_fd, int report) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);  // the parent died before prctl: nobody is left to kill us
  ::setpgid(0, 0);
  // What duet blocked or ignored is not the program's business: exec keeps both.
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (const int number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT}) ::sigaction(number, &default_action, nullptr);
  ::dup2(null_fd, STDIN_FILENO);
  if (out_fd >= 0) ::dup2(out_fd, STDOUT_FILENO);
  if (err_fd >= 0) ::dup2(err_fd, STDERR_FILENO);
  ::execvp(argv[0], argv);
  const int error = errno;
  [[maybe_unused]] const ssize_t written = ::write(report, &error, sizeof error);
  ::_exit(127);
}

}  // namespace

Result<ChildProcess> ChildProcess::start(const std::vector<std::string>& command, Outputs outputs) {
  if (command.empty()) return Failure{"no program to run"};
  std::vector<std::string> words = command;
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  Descriptors descriptors;
  const int null_fd = descriptors.keep(::open("/dev/null", O_RDWR | O_CLOEXEC));
  int report[2] = {-1, -1};
  if (null_fd < 0 || ::pipe2(report, O_CLOEXEC) != 0) return Failure{std::string{"pipe: "} + std::strerror(errno)};
  descriptors.keep(report[0]);
  descriptors.keep(report[1]);
  // The child's end of each output: /dev/null, a new pipe's writing end, or none (inherited).
  const auto child_end = [&](Output output, int& parent_end) -> Result<int> {
    if (output == Output::inherit) return -1;
    if (output == Output::discard) return null_fd;
    int ends[2] = {-1, -1};
    if (::pipe2(ends, O_CLOEXEC) != 0) return Failure{std::string{"pipe: "} + std::strerror(errno)};
    parent_end = descriptors.keep(ends[0]);
    return descriptors.keep(ends[1]);
  };
  int output_fd = -1;
  int errors_fd = -1;
  auto out_end = child_end(outputs.out, output_fd);
  if (!out_end) return Failure{out_end.error()};
  auto err_end = child_end(outputs.err, errors_fd);
  if (!err_end) return Failure{err_end.error()};

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) return Failure{"cannot start " + command.front() + ": fork: " + std::strerror(errno)};
  if (pid == 0) become(argv.data(), parent, null_fd, out_end.value(), err_end.value(), report[1]);

  ::close(descriptors.release(report[1]));
  int error = 0;
  ssize_t got = 0;
  do {
    got = ::read(report[0], &error, sizeof error);  // nothing (the end of the pipe) once exec succeeded
  } while (got < 0 && errno == EINTR);
  if (got == static_cast<ssize_t>(sizeof error)) {
    ::waitpid(pid, nullptr, 0);
    return Failure{"cannot run " + command.front() + ": " + std::strerror(error)};
  }
  return ChildProcess{pid, output_fd >= 0 ? descriptors.release(output_fd) : -1,
                      errors_fd >= 0 ? descriptors.release(errors_fd) : -1};
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(std::exchange(other.pid_, -1)),
      output_fd_(std::exchange(other.output_fd_, -1)),
      errors_fd_(std::exchange(other.errors_fd_, -1)),
      exit_code_(other.exit_code_) {}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this != &other) {
    release();
    pid_ = std::exchange(other.pid_, -1);
    output_fd_ = std::exchange(other.output_fd_, -1);
    errors_fd_ = std::exchange(other.errors_fd_, -1);
    exit_code_ = other.exit_code_;
  }
  return *this;
}

ChildProcess::~ChildProcess() { release(); }

void ChildProcess::release() {
  if (pid_ > 0 && !exit_code_) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  for (int* fd : {&output_fd_, &errors_fd_}) {
    if (*fd >= 0) ::close(std::exchange(*fd, -1));
  }
  pid_ = -1;
}

std::optional<int> ChildProcess::exit_code() {
  if (exit_code_ || pid_ <= 0) return exit_code_;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) exit_code_ = exit_code_of(status);
  return exit_code_;
}

void ChildProcess::signal(int number) {
  if (pid_ > 0 && !exit_code()) ::kill(pid_, number);
}

int ChildProcess::stop(std::chrono::milliseconds grace) { return stop(grace, SIGTERM); }

int ChildProcess::stop(std::chrono::milliseconds grace, int first) {
  signal(first);
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (!exit_code() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds{10});
  }
  if (!exit_code()) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exit_code_ = exit_code_of(status);
  }
  return *exit_code_;
}

}  // namespace duet::cli
