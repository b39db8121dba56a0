// Result files that are never torn and never written through a planted link (issue 22).
// Two kinds of file:
// * files written whole at the end (envelopes, statistics, the checkpoint): written to a
//   fresh temporary file in the same directory (mkstemp: O_CREAT | O_EXCL, so a symbolic
//   link or any other file planted under the temporary name is never opened) and renamed
//   over the target, so they are complete or absent (the previous version stays);
// * files that grow by rows (timeseries.csv, <beam>.along.csv): opened with O_NOFOLLOW,
//   each row is one write(2); a failed write (disk full, EFBIG) cuts the file back to the
//   end of its last whole row, so it never ends in a partial line.
// Every failure throws OutputError naming the file: the CLI reports it with exit code 3.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace seaflex {

/// A result file that could not be written (disk full, file size limit, permissions, a
/// symbolic link in the way). what(): "cannot write PATH: reason".
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::filesystem::path& path, const std::string& reason);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// Writes text to path through a temporary file in path's directory, renamed over path.
/// Never follows a link planted at the temporary name; replaces a link at path itself
/// (rename replaces the directory entry, not the link's target). Throws OutputError.
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

/// A file of rows: fresh (truncated; a symbolic link at path is refused) or continued
/// from a known length (resume). Each append() is one write; on failure the file is cut
/// back to its last whole row and OutputError is thrown.
class RowFile {
 public:
  RowFile() = default;
  /// Creates (truncates) path. Throws OutputError.
  explicit RowFile(const std::filesystem::path& path);
  /// Opens path to continue after its first `bytes` bytes (the rest is cut off). Throws
  /// OutputError when path is missing, not a regular file or shorter than bytes.
  RowFile(const std::filesystem::path& path, std::uintmax_t bytes);
  ~RowFile();
  RowFile(RowFile&& other) noexcept;
  RowFile& operator=(RowFile&& other) noexcept;
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  bool is_open() const { return fd_ >= 0; }
  /// Appends whole rows (text ends with '\n'). Throws OutputError (the file keeps its
  /// previous rows).
  void append(std::string_view text);
  /// Bytes of whole rows written so far.
  std::uintmax_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void close() noexcept;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
  bool cut_ = false;  // resumed: cut back to size_ before the first append
  std::filesystem::path path_;
};

}  // namespace seaflex
