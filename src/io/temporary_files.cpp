#include "animkit/io/temporary_files.h"

#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "cleanup_registry.h"

namespace animkit {

namespace {

constexpr std::string_view kMarker = ".animkit-";
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Everything a dying run must remove or kill, in registration order. One mutex guards it; the
// signal thread takes it and never gives it back, so nothing registers after the clean-up.
struct Registry {
  std::mutex mutex;
  int next_id = 1;
  std::map<int, std::filesystem::path> paths;
  std::map<pid_t, int> children;  // pid -> handles holding it
};

Registry& registry() {
  static Registry* r = new Registry;  // never destroyed: the signal thread may outlive main
  return *r;
}

std::uint64_t random_bits() {
  // Unique across processes by the pid in the name; across calls and threads by this counter
  // mixed with a per-process random seed (a leftover of a dead process with a recycled pid
  // must not collide either).
  static std::atomic<std::uint64_t> counter{std::random_device{}()};
  std::uint64_t z = counter.fetch_add(0x9E3779B97F4A7C15ull) + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;  // splitmix64
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

bool process_is_gone(pid_t pid) {
  return pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH;
}

[[noreturn]] void clean_up_and_die(int signal_number) {
  Registry& r = registry();
  r.mutex.lock();  // held until the process is gone
  for (const auto& [pid, holders] : r.children) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
  }
  for (auto it = r.paths.rbegin(); it != r.paths.rend(); ++it) {
    std::error_code ignored;
    std::filesystem::remove_all(it->second, ignored);
  }
  // Die of the signal itself, so the parent sees what happened (a shell prints nothing for
  // SIGINT and stops a script).
  std::signal(signal_number, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal_number);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  ::raise(signal_number);
  std::_Exit(128 + signal_number);
}

}  // namespace

namespace detail {

std::unique_lock<std::mutex> lock_cleanup_registry() {
  return std::unique_lock<std::mutex>(registry().mutex);
}

}  // namespace detail

std::filesystem::path unique_sibling(const std::filesystem::path& path, std::string_view kind) {
  char suffix[64];
  std::snprintf(suffix, sizeof suffix, "%.*s%ld-%012llx.", static_cast<int>(kMarker.size()),
                kMarker.data(), static_cast<long>(::getpid()),
                static_cast<unsigned long long>(random_bits() & 0xFFFFFFFFFFFFull));
  std::filesystem::path sibling = path;
  sibling += suffix;
  sibling += std::string(kind);
  return sibling;
}

bool is_animkit_temporary(std::string_view name, pid_t& pid) {
  const std::size_t marker = name.rfind(kMarker);
  if (marker == std::string_view::npos || marker == 0) return false;
  std::string_view rest = name.substr(marker + kMarker.size());
  long value = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
  if (error != std::errc() || value <= 0 || end == rest.data() + rest.size() || *end != '-') {
    return false;
  }
  rest.remove_prefix(static_cast<std::size_t>(end - rest.data()) + 1);
  if (rest.size() < 14 || rest[12] != '.') return false;
  for (std::size_t i = 0; i < 12; ++i) {
    if (!std::isxdigit(static_cast<unsigned char>(rest[i]))) return false;
  }
  const std::string_view kind = rest.substr(13);
  if (kind != "tmp" && kind != "log" && kind != "staging" && kind != "old") return false;
  pid = static_cast<pid_t>(value);
  return true;
}

CleanupHandle::CleanupHandle(const std::filesystem::path& path) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  id_ = r.next_id++;
  r.paths.emplace(id_, path);
}

CleanupHandle::CleanupHandle(CleanupHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

CleanupHandle& CleanupHandle::operator=(CleanupHandle&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

CleanupHandle::~CleanupHandle() {
  release();
}

void CleanupHandle::release() {
  if (id_ == 0) return;
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.paths.erase(std::exchange(id_, 0));
}

ChildHandle::ChildHandle(pid_t pid) : pid_(pid) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  ++r.children[pid_];
}

ChildHandle::ChildHandle(ChildHandle&& other) noexcept : pid_(std::exchange(other.pid_, 0)) {}

ChildHandle& ChildHandle::operator=(ChildHandle&& other) noexcept {
  if (this != &other) {
    release();
    pid_ = std::exchange(other.pid_, 0);
  }
  return *this;
}

ChildHandle::~ChildHandle() {
  release();
}

void ChildHandle::release() {
  if (pid_ == 0) return;
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  if (auto it = r.children.find(pid_); it != r.children.end() && --it->second == 0) {
    r.children.erase(it);
  }
  pid_ = 0;
}

void install_signal_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kCleanupSignals) sigaddset(&set, s);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set] {
      int received = 0;
      while (sigwait(&set, &received) != 0) {
      }
      clean_up_and_die(received);
    }).detach();
  });
}

void remove_stale_temporaries(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::directory_iterator it(folder, error), end;
  if (error) return;
  for (; it != end; it.increment(error)) {
    if (error) return;
    const std::string name = it->path().filename().string();
    pid_t pid = 0;
    if (!is_animkit_temporary(name, pid) || !process_is_gone(pid)) continue;
    std::error_code ignored;
    if (name.ends_with(".old")) {
      // A swap that died between its renames: the previous results are here, not in place.
      const std::filesystem::path original =
          it->path().parent_path() / name.substr(0, name.rfind(kMarker));
      if (!std::filesystem::exists(std::filesystem::symlink_status(original, ignored))) {
        std::filesystem::rename(it->path(), original, ignored);
        if (!ignored) continue;
      }
    }
    std::filesystem::remove_all(it->path(), ignored);
  }
}

}  // namespace animkit
