// The files a model reads, for restart files (issue 22): a resumed run must read the same
// inputs as the run that wrote the checkpoint, so the checkpoint holds a hash of the model
// file and of every file it names. Which strings name files is found without the loader:
// every text value of the model that names an existing regular file (relative to the
// model's directory, as the loader resolves them: motion and RAO tables, WAMIT .4 files),
// and for every `wamit` key its stem's .1, .3 and .hst (also when absent: a file that
// appears later changes the run too).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace seaflex::io {

/// The largest model or input file hashed for a checkpoint (bytes).
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{4} << 30;  // 4 GiB

/// The input files of the model file (absolute paths, sorted, without the model itself).
/// Throws InputError when the model is not a readable YAML file.
std::vector<std::string> model_input_files(const std::string& model_file);

/// FNV-1a (64 bits, hex) of a file's bytes, read in blocks; "absent" for a path that does
/// not exist. Throws InputError naming `key` for a path that is not a regular file or is
/// larger than kMaxInputFileBytes (a device or FIFO is never read).
std::string input_file_hash(const std::string& path, const std::string& key);

}  // namespace seaflex::io
