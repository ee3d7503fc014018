// The files one command writes, committed together: each goes to its own temporary, and only
// when every one is complete are they renamed into place, so a failure replaces none of them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "output/temporary_file.h"

namespace radiant {

class OutputSet {
 public:
  // A new temporary for `target` (TemporaryFile's errors, resolve_output_target's refusals).
  // A target that is a character device or a FIFO (or a symlink to one) is streamed through
  // like standard output: its temporary lives in the temporary folder, and the finished bytes
  // are written into the target when committed. A symlink to a regular file stays a link: the
  // file it leads to is replaced.
  TemporaryFile& create(const std::string& target);
  // A temporary whose bytes go to standard output when committed: it lives in the temporary
  // folder ($TMPDIR, else /tmp) under a name with `extension`, which names the format.
  TemporaryFile& create_standard_output(const std::string& extension);
  // Finishes every file, then renames each onto its target or streams it. Throws
  // std::runtime_error naming the file that failed; when a finish fails, no target has been
  // touched. (The renames themselves are separate steps: one failing after another succeeded is
  // not undone, but a rename within a folder fails only when the folder changed under the
  // command.)
  void commit();
  // Leaves `file` out of the commit and removes it (a chart that could not be drawn).
  void remove(const TemporaryFile& file);

 private:
  // A temporary whose bytes are copied into `destination` ("-": standard output), never renamed.
  struct Stream {
    const TemporaryFile* file;
    std::string destination;
  };
  TemporaryFile& create_streamed(const std::string& target, const std::string& extension, const std::string& destination);
  std::vector<std::unique_ptr<TemporaryFile>> files_;
  std::vector<Stream> streams_;
};

}  // namespace radiant
