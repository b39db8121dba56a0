// The one way seaflex reads an input file (issue 22): the model, the WAMIT files, motion and
// RAO tables, scatter diagrams and result tables read back by `stats`. Only regular files
// are read, whole and up to a stated size, so that a device (/dev/zero, /dev/urandom), a FIFO,
// a directory or a symbolic link loop gives a plain message naming the file instead of a
// memory blow-up, a hang in open(2) or an unlocated filesystem error:
//   model.yaml: cannot read the model file: it is a directory
//   hull.1: file: cannot read the WAMIT file: it is not a regular file (a character device,
//           through the symbolic link to '/dev/zero')
// The file is opened with O_NONBLOCK, so that a FIFO put in its place between the check and
// the open never blocks, and checked again with fstat(2) after the open.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace seaflex {

/// The largest model file (YAML) read: 4 MiB, 400 times the largest example. A model names
/// its large data (WAMIT files, motion tables) in files of their own. yaml-cpp needs up to
/// about 115 bytes of memory and 1 us per byte of YAML (a list of small numbers: 14.6 MB
/// took 1.67 GB and 15 s), so a model file costs at most about 0.5 GB and 4 s to parse.
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{4} << 20;
/// The largest data file read (WAMIT .1/.3/.hst, motion and RAO tables, result tables):
/// 256 MiB, ten times a WAMIT run of 500 periods x 36 headings.
inline constexpr std::uintmax_t kMaxDataFileBytes = std::uintmax_t{256} << 20;

/// The whole content of the regular file at path (symbolic links are followed).
/// what names the file in messages ("model file", "WAMIT file"); key is the key of the
/// Diagnostic ("" or e.g. "file").
/// Throws seaflex::InputError with one Diagnostic{path, 0, 0, key, "cannot read the <what>:
/// <reason>"} when the file does not exist, cannot be opened (permission), is not a regular
/// file (a directory, FIFO, character or block device, socket), is a symbolic link loop, is
/// larger than max_bytes, or a read fails. A reason that comes through a symbolic link names
/// the link's final target.
std::string read_input_file(const std::string& path, std::string_view what,
                            std::uintmax_t max_bytes = kMaxDataFileBytes,
                            const std::string& key = "");

/// True when anything is at path (lstat(2)): a file, a directory, a device, a FIFO, a
/// symbolic link even if dangling or looping. For optional files: what is there is read
/// with read_input_file, which says what is wrong with it. Never throws.
bool input_file_present(const std::string& path);

/// "12.3 MiB" style size for messages (binary units, 3 significant digits).
std::string describe_size(std::uintmax_t bytes);

}  // namespace seaflex
