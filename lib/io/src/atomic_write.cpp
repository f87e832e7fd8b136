#include "shpack/io/atomic_write.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
#include <system_error>
#include <utility>

namespace shpack::io {
namespace {

namespace fs = std::filesystem;

std::string errno_text(int e) { return std::generic_category().message(e); }

// ---- live temporaries, removed by SIGINT, SIGTERM and SIGHUP -----------------------------
//
// A fixed table the signal handler reads without locks: each slot holds the folder's
// descriptor and the temporary's name while the temporary may exist (from just before it is
// created to just after it is renamed or removed). The handler only calls unlinkat, signal
// and raise, which are async-signal-safe.

constexpr std::size_t kSlots = 64;
constexpr std::size_t kNameMax = 256;  // NAME_MAX + 1
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

enum SlotState : int { kFree = 0, kBusy = 1, kLive = 2 };
static_assert(std::atomic<int>::is_always_lock_free);

struct Slot {
  std::atomic<int> state{kFree};
  int dirfd = -1;
  char name[kNameMax] = {};
};
Slot g_slots[kSlots];

extern "C" void remove_temporaries_and_reraise(int sig) {
  const int saved = errno;
  for (Slot& slot : g_slots)
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlinkat(slot.dirfd, slot.name, 0);
  // The signal is blocked while this runs: it is delivered again, with the default action
  // (ending the process), as soon as the handler returns.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
  errno = saved;
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0) continue;
      if ((old.sa_flags & SA_SIGINFO) != 0 || old.sa_handler != SIG_DFL) continue;  // ignored or the program's
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      for (int other : kSignals) sigaddset(&action.sa_mask, other);
      ::sigaction(sig, &action, nullptr);
    }
  });
}

// One slot of the table for the lifetime of a temporary; no slot (the table full, or a name
// too long) means no removal on a signal, never a failed write.
class LiveTemporary {
 public:
  LiveTemporary() = default;
  void claim(int dirfd, const std::string& name) {
    release();
    if (name.size() >= kNameMax) return;
    for (Slot& slot : g_slots) {
      int expected = kFree;
      if (!slot.state.compare_exchange_strong(expected, kBusy, std::memory_order_acq_rel)) continue;
      slot.dirfd = dirfd;
      std::memcpy(slot.name, name.c_str(), name.size() + 1);
      slot.state.store(kLive, std::memory_order_release);
      slot_ = &slot;
      return;
    }
  }
  ~LiveTemporary() { release(); }
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;
  void release() {
    if (slot_ != nullptr) slot_->state.store(kFree, std::memory_order_release);
    slot_ = nullptr;
  }

 private:
  Slot* slot_ = nullptr;
};

// ---- helpers -----------------------------------------------------------------------------

class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

// Test hook (tests/io/output_safety_test.cpp): with SHPACK_TEST_PAUSE_IN_WRITE set, a write
// to a temporary stops after its first chunk until a signal ends the process, so a test can
// interrupt a write in the middle deterministically.
bool pause_in_write() {
  static const bool pause = std::getenv("SHPACK_TEST_PAUSE_IN_WRITE") != nullptr;
  return pause;
}

// Writes all of `contents` to `fd` in chunks; 0 or the errno.
int write_all(int fd, std::string_view contents, bool is_temporary) {
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::size_t done = 0;
  while (done < contents.size()) {
    const std::size_t n = std::min(kChunk, contents.size() - done);
    const ssize_t wrote = ::write(fd, contents.data() + done, n);
    if (wrote < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(wrote);
    if (is_temporary && pause_in_write())
      for (;;) ::pause();
  }
  return 0;
}

// The process's umask, without changing it (umask(2) can only be read by setting it, which
// would race with the other threads): from /proc/self/status, else the common 022.
mode_t current_umask() {
  static const mode_t mask = [] {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
      if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8) & 0777);
    }
    return static_cast<mode_t>(022);
  }();
  return mask;
}

// ".<name>.<10 random letters and digits>", the name cut so the whole fits NAME_MAX.
std::string temporary_name(const std::string& name) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  constexpr std::size_t kRandom = 10;
  unsigned char bytes[kRandom];
  if (::getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes)) {
    // No entropy source: still unique enough with the clock, the pid and a counter; the
    // O_EXCL create is what keeps it safe, the randomness only keeps it from being guessed.
    static std::atomic<unsigned long long> counter{0};
    unsigned long long x = static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                           (static_cast<unsigned long long>(::getpid()) << 32) ^ (counter++ * 0x9E3779B97F4A7C15ull);
    for (unsigned char& b : bytes) {
      x ^= x >> 33;
      x *= 0xff51afd7ed558ccdull;
      b = static_cast<unsigned char>(x >> 56);
    }
  }
  // Appended piece by piece: g++ 12 at -O3 reports a false -Wrestrict on "." + substr.
  std::string out(1, '.');
  out.append(name, 0, 255 - 2 - kRandom);
  out += '.';
  for (unsigned char b : bytes) out += kAlphabet[b % (sizeof kAlphabet - 1)];
  return out;
}

IoStatus fail(const fs::path& path, const std::string& problem) {
  return IoStatus::error(IoErrc::WriteFailed, path, problem);
}

// Writes to an open descriptor, in place.
IoStatus write_in_place(const fs::path& path, int fd, std::string_view contents) {
  if (const int e = write_all(fd, contents, false); e != 0) return fail(path, "cannot write: " + errno_text(e));
  return IoStatus::success();
}

// Opens the existing non-regular file `name` of `dirfd` for writing and writes it in place.
IoStatus write_special(const fs::path& path, int dirfd, const std::string& name, bool follow,
                       std::string_view contents) {
  const int flags = O_WRONLY | O_NOCTTY | O_CLOEXEC | (follow ? 0 : O_NOFOLLOW);
  const Fd fd(::openat(dirfd, name.c_str(), flags));
  if (fd.get() < 0) return fail(path, "cannot open for writing: " + errno_text(errno));
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) return fail(path, "cannot check: " + errno_text(errno));
  if (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode))  // changed since it was looked at
    return fail(path, "changed while it was opened; nothing written");
  return write_in_place(path, fd.get(), contents);
}

// Writes a temporary in `dirfd` and renames it over `name`. `old`: the regular file being
// replaced (its mode and owner are kept), or null.
IoStatus replace(const fs::path& path, int dirfd, bool dir_syncable, const std::string& name, const struct stat* old,
                 std::string_view contents) {
  install_handlers_once();
  std::string temp;
  Fd fd;
  LiveTemporary live;
  for (int attempt = 0; attempt < 100 && fd.get() < 0; ++attempt) {
    temp = temporary_name(name);
    live.claim(dirfd, temp);  // before the file exists: a signal cannot slip in between
    fd.reset(::openat(dirfd, temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600));
    if (fd.get() < 0) {
      const int e = errno;
      live.release();
      if (e != EEXIST) return fail(path, "cannot create a temporary file next to it: " + errno_text(e));
    }
  }
  if (fd.get() < 0) return fail(path, "cannot create a temporary file next to it: every name taken");

  std::string problem;
  if (const int e = write_all(fd.get(), contents, true); e != 0) problem = "cannot write: " + errno_text(e);
  if (problem.empty()) {
    mode_t mode = 0666 & ~current_umask();
    if (old != nullptr) {
      mode = old->st_mode & 0777;  // permission bits; never set-id bits on a new file
      if (::geteuid() == 0 && (old->st_uid != 0 || old->st_gid != 0))
        (void)!::fchown(fd.get(), old->st_uid, old->st_gid);  // best effort: root keeps the owner
    }
    if (::fchmod(fd.get(), mode) != 0) problem = "cannot set the mode: " + errno_text(errno);
  }
  if (problem.empty() && ::fsync(fd.get()) != 0) problem = "cannot write: " + errno_text(errno);
  if (::close(fd.release()) != 0 && problem.empty()) problem = "cannot write: " + errno_text(errno);
  if (problem.empty() && ::renameat(dirfd, temp.c_str(), dirfd, name.c_str()) != 0)
    problem = "cannot replace the file: " + errno_text(errno);
  if (!problem.empty()) {
    ::unlinkat(dirfd, temp.c_str(), 0);
    return fail(path, problem);
  }
  live.release();
  if (dir_syncable) ::fsync(dirfd);  // the rename itself, durable; a failure here loses nothing
  return IoStatus::success();
}

// "/dev/fd/N" or "/proc/self/fd/N": N, else -1.
int descriptor_number(const std::string& text, std::string_view prefix) {
  if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0) return -1;
  int n = 0;
  for (std::size_t k = prefix.size(); k < text.size(); ++k) {
    if (text[k] < '0' || text[k] > '9' || n > 100000) return -1;
    n = n * 10 + (text[k] - '0');
  }
  return n;
}

}  // namespace

int output_descriptor(const fs::path& path) {
  const std::string& text = path.native();
  if (text == "-" || text == "/dev/stdout") return STDOUT_FILENO;
  if (text == "/dev/stderr") return STDERR_FILENO;
  if (text == "/dev/stdin") return STDIN_FILENO;
  if (const int n = descriptor_number(text, "/dev/fd/"); n >= 0) return n;
  return descriptor_number(text, "/proc/self/fd/");
}

IoStatus write_file_atomically(const fs::path& path, std::string_view contents) {
  if (const int fd = output_descriptor(path); fd >= 0) {
    if (::fcntl(fd, F_GETFD) < 0) return fail(path, "cannot write: the descriptor is not open");
    return write_in_place(path, fd, contents);
  }
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..") return fail(path, "is a directory");
  const fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  bool syncable = true;
  Fd dir(::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.get() < 0 && errno == EACCES) {  // a folder one may write but not list: still usable
    syncable = false;
    dir.reset(::open(parent.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC));
  }
  if (dir.get() < 0) return fail(path, "cannot create the file: " + parent.string() + ": " + errno_text(errno));

  struct stat st {};
  if (::fstatat(dir.get(), name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    if (errno != ENOENT) return fail(path, "cannot check: " + errno_text(errno));
    return replace(path, dir.get(), syncable, name, nullptr, contents);  // a new file
  }
  if (S_ISREG(st.st_mode)) return replace(path, dir.get(), syncable, name, &st, contents);
  if (S_ISDIR(st.st_mode)) return fail(path, "is a directory");
  if (S_ISLNK(st.st_mode)) {
    struct stat target {};
    if (::fstatat(dir.get(), name.c_str(), &target, 0) != 0 || S_ISREG(target.st_mode))
      return replace(path, dir.get(), syncable, name, nullptr, contents);  // the link itself is replaced
    if (S_ISDIR(target.st_mode)) return fail(path, "is a link to a directory");
    if (st.st_uid != ::geteuid() && st.st_uid != 0)
      return fail(path, "is a link owned by another user to a device, FIFO or socket; not written through");
    return write_special(path, dir.get(), name, true, contents);
  }
  return write_special(path, dir.get(), name, false, contents);  // a device, FIFO or socket
}

}  // namespace shpack::io
