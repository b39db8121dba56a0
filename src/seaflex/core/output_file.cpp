#include "seaflex/core/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace seaflex {

namespace {

// the process's umask, read once (umask(2) can only be read by setting it)
mode_t file_mode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(022);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

std::string reason(int err) {
  if (err == ELOOP)
    return "it is a symbolic link (refused: results are never written through a link)";
  if (err == EFBIG) return fmt::format("{} (the file size limit, ulimit -f)", std::strerror(err));
  if (err == ENOSPC) return fmt::format("{} (the disk is full)", std::strerror(err));
  return std::strerror(err);
}

// writes all of text at offset; false (errno set) on failure
bool write_all(int fd, std::string_view text, off_t offset) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n =
        ::pwrite(fd, text.data() + done, text.size() - done, offset + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) {
      errno = EIO;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

OutputError::OutputError(const std::filesystem::path& path, const std::string& why)
    : std::runtime_error(fmt::format("cannot write {}: {}", path.string(), why)), path_(path) {}

void write_file_atomically(const std::filesystem::path& path, std::string_view text) {
  // mkstemp creates the file with O_CREAT | O_EXCL: nothing planted is ever opened
  const std::string pattern =
      (path.parent_path() / (path.filename().string() + ".tmp.XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError(path, reason(errno));
  const std::string tmp(name.data());
  const auto fail = [&](int err) {
    ::unlink(tmp.c_str());
    throw OutputError(path, reason(err));
  };
  if (::fchmod(fd, file_mode()) != 0 || !write_all(fd, text, 0)) {
    const int err = errno;
    ::close(fd);
    fail(err);
  }
  if (::close(fd) != 0) fail(errno);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(errno);
}

RowFile::RowFile(const std::filesystem::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd_ < 0) throw OutputError(path, reason(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    close();
    throw OutputError(path, "not a regular file");
  }
}

RowFile::RowFile(const std::filesystem::path& path, std::uintmax_t bytes)
    : size_(bytes), path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd_ < 0) throw OutputError(path, reason(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    close();
    throw OutputError(path, "not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) < bytes) {
    close();
    throw OutputError(path, fmt::format("{} bytes, fewer than the {} expected", st.st_size, bytes));
  }
  // cut back to `bytes` only at the first append: a resume refused later leaves the file
  // untouched
  cut_ = static_cast<std::uintmax_t>(st.st_size) > bytes;
}

RowFile::~RowFile() {
  close();
}

RowFile::RowFile(RowFile&& other) noexcept
    : fd_(other.fd_), size_(other.size_), cut_(other.cut_), path_(std::move(other.path_)) {
  other.fd_ = -1;
}

RowFile& RowFile::operator=(RowFile&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = other.fd_;
    size_ = other.size_;
    cut_ = other.cut_;
    path_ = std::move(other.path_);
    other.fd_ = -1;
  }
  return *this;
}

void RowFile::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void RowFile::append(std::string_view text) {
  if (fd_ < 0) throw OutputError(path_, "the file is not open");
  if (cut_) {
    if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) throw OutputError(path_, reason(errno));
    cut_ = false;
  }
  if (!write_all(fd_, text, static_cast<off_t>(size_))) {
    const int err = errno;
    // cut the partial row off: the file ends with its last whole row
    if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {
      // nothing more can be done; the message says the last row may be partial
      throw OutputError(path_, fmt::format("{}; cutting off the partial row failed too: {}",
                                           reason(err), std::strerror(errno)));
    }
    throw OutputError(path_, reason(err));
  }
  size_ += text.size();
}

}  // namespace seaflex
