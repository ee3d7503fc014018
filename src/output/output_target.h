// What a path given as an output is, decided before anything is written: a regular file (new or
// replaced by rename), or a character device or FIFO that the output streams through, as to
// standard output. Everything else is refused, so that no output ever turns a device, a FIFO
// or a symlink into a regular file.
#pragma once

#include <string>

namespace radiant {

enum class OutputKind {
  file,    // written beside `path` and renamed onto it
  stream,  // `path` is opened for writing and the finished bytes copied into it
};

struct OutputTarget {
  OutputKind kind = OutputKind::file;
  // The file to rename onto or to open: the target itself, or what its symlinks resolve to, so
  // that a symlink stays a link and the file it points to is written.
  std::string path;
};

// Resolves `target` (not "-"). Throws std::runtime_error "cannot write 'TARGET': WHY" when it
// is a folder, a block device or a socket, a symlink to nothing, or an existing file that is
// read-only (no write permission bit, or none for this process).
OutputTarget resolve_output_target(const std::string& target);

}  // namespace radiant
