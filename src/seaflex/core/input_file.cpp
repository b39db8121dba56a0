#include "seaflex/core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "seaflex/core/errors.hpp"

namespace seaflex {

namespace {

// the kind of a file that is not a regular file, for "it is not a regular file (a FIFO)"
std::string kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

// ", through the symbolic link to 'target'" when path is a symbolic link; "" otherwise
std::string through_link(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return "";
  const std::unique_ptr<char, decltype(&std::free)> target(::realpath(path.c_str(), nullptr),
                                                           &std::free);
  if (target) return fmt::format(", through the symbolic link to '{}'", target.get());
  char buffer[PATH_MAX];
  const ssize_t n = ::readlink(path.c_str(), buffer, sizeof buffer - 1);
  if (n <= 0) return ", through a symbolic link";
  return fmt::format(", through the symbolic link to '{}'", std::string(buffer, n));
}

// the reason an open(2) or stat(2) failed with errno e
std::string open_failure(const std::string& path, int e) {
  switch (e) {
    case ENOENT: {
      struct stat st {};
      if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
        char buffer[PATH_MAX];
        const ssize_t n = ::readlink(path.c_str(), buffer, sizeof buffer - 1);
        return fmt::format("it is a symbolic link to '{}', which does not exist",
                           n > 0 ? std::string(buffer, n) : std::string("?"));
      }
      return "no such file";
    }
    case ELOOP:
      return "it is a symbolic link loop (too many levels of symbolic links)";
    case EACCES:
    case EPERM:
      return "permission denied";
    case ENOTDIR:
      return "a part of its path is not a directory";
    case ENAMETOOLONG:
      return "its name is too long";
    default:
      return std::strerror(e);
  }
}

// the reason the file described by st cannot be read, "" when it can
std::string refusal(const std::string& path, const struct stat& st, std::uintmax_t max_bytes,
                    std::string_view what) {
  if (S_ISDIR(st.st_mode)) return "it is a directory" + through_link(path);
  if (!S_ISREG(st.st_mode))
    return fmt::format("it is not a regular file ({}{})", kind_of(st.st_mode), through_link(path));
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    return fmt::format("it is {}, more than {} (the limit for the {})", describe_size(st.st_size),
                       describe_size(max_bytes), what);
  return "";
}

}  // namespace

std::string describe_size(std::uintmax_t bytes) {
  const double b = static_cast<double>(bytes);
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  if (b < 1024.0 * 1024.0) return fmt::format("{:.3g} KiB", b / 1024.0);
  if (b < 1024.0 * 1024.0 * 1024.0) return fmt::format("{:.3g} MiB", b / (1024.0 * 1024.0));
  return fmt::format("{:.3g} GiB", b / (1024.0 * 1024.0 * 1024.0));
}

bool input_file_present(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

std::string read_input_file(const std::string& path, std::string_view what,
                            std::uintmax_t max_bytes, const std::string& key) {
  const auto fail = [&](const std::string& reason) {
    return InputError(
        {Diagnostic{path, 0, 0, key, fmt::format("cannot read the {}: {}", what, reason)}});
  };
  // stat first: a device or FIFO is never opened (opening some devices has effects)
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw fail(open_failure(path, errno));
  if (const std::string why = refusal(path, st, max_bytes, what); !why.empty()) throw fail(why);
  // O_NONBLOCK: a FIFO swapped in since the stat cannot block the open
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw fail(open_failure(path, errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &st) != 0) throw fail(std::strerror(errno));
  if (const std::string why = refusal(path, st, max_bytes, what); !why.empty()) throw fail(why);
  // read up to the limit (a file may grow while read, and /proc files report size 0)
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw fail(fmt::format("a read failed: {}", std::strerror(errno)));
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > max_bytes)
      throw fail(fmt::format("it grew beyond {} (the limit for the {}) while it was read",
                             describe_size(max_bytes), what));
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace seaflex
