#include "child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>

extern char** environ;

namespace animkit::detail {

Result<pid_t> spawn_program(const std::vector<std::string>& argv, int stdin_fd, int stdout_fd,
                            int stderr_fd) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const int fds[3] = {stdin_fd, stdout_fd, stderr_fd};
  for (int target = 0; target < 3; ++target) {
    if (fds[target] < 0) {
      posix_spawn_file_actions_addopen(&actions, target, "/dev/null",
                                       target == 0 ? O_RDONLY : O_WRONLY, 0);
    } else {
      posix_spawn_file_actions_adddup2(&actions, fds[target], target);
    }
  }
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0) return fail(argv[0] + " did not start (" + std::strerror(error) + ")");
  return pid;
}

int wait_program(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

Result<std::string> run_program_output(const std::vector<std::string>& argv) {
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return fail(argv[0] + ": " + std::strerror(errno));
  auto pid = spawn_program(argv, -1, out[1], -1);
  ::close(out[1]);
  if (!pid) {
    ::close(out[0]);
    return fail(pid.error().message);
  }
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(out[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (text.size() < 65536) text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(out[0]);
  const int status = wait_program(*pid);
  if (status != 0) return fail(argv[0] + " exited with status " + std::to_string(status));
  return text;
}

struct PipeCollector::State {
  int read_end = -1, write_end = -1;
  std::thread reader;
  std::string text;

  ~State() {
    if (write_end >= 0) ::close(write_end);
    if (reader.joinable()) reader.join();
    if (read_end >= 0) ::close(read_end);
  }
};

PipeCollector::PipeCollector() : state_(std::make_unique<State>()) {}
PipeCollector::PipeCollector(PipeCollector&&) noexcept = default;
PipeCollector& PipeCollector::operator=(PipeCollector&&) noexcept = default;
PipeCollector::~PipeCollector() = default;

Result<PipeCollector> PipeCollector::open() {
  PipeCollector collector;
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) return fail(std::string("pipe: ") + std::strerror(errno));
  collector.state_->read_end = ends[0];
  collector.state_->write_end = ends[1];
  return collector;
}

int PipeCollector::child_end() const {
  return state_->write_end;
}

void PipeCollector::start() {
  State& s = *state_;
  ::close(s.write_end);
  s.write_end = -1;
  s.reader = std::thread([&s] {
    constexpr std::size_t kKeep = 16384;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(s.read_end, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      s.text.append(buffer, static_cast<std::size_t>(n));
      if (s.text.size() > 2 * kKeep) s.text.erase(0, s.text.size() - kKeep);
    }
  });
}

std::string PipeCollector::finish() {
  if (state_->reader.joinable()) state_->reader.join();
  return state_->text;
}

}  // namespace animkit::detail
