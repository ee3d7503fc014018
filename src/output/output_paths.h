// Where radiant may write, checked before any work: a render is never spent on an output that
// cannot be written, and an output never replaces another output or an input.
#pragma once

#include <compare>
#include <map>
#include <string>
#include <vector>

namespace radiant {

// `-o -` and `--stats -`: the output goes to standard output (a pipe) instead of a file.
inline bool is_standard_output(const std::string& target) { return target == "-"; }

// Throws std::runtime_error "cannot write 'TARGET': WHY" when no file can be created at
// `target`: its folder is missing, is not a folder or is not writable by this process, or
// `target` itself is refused by resolve_output_target (output_target.h): a folder, a read-only
// file, a block device... A symlink's folder is that of the file it leads to. Standard output
// ("-") must be open.
void check_output_place(const std::string& target);

// The same for a folder that is created when missing (converge --out): `folder`, or else its
// nearest existing ancestor, must be a folder this process can write in.
void check_output_folder(const std::string& folder);

// A file a command reads or writes, with the flag or role that named it, for messages.
struct NamedFile {
  std::string name;  // "-o", "--stats", "the scene", ...
  std::string path;
};

// The files one command reads and writes, so that no output is written over another output or
// over an input. Two paths are the same file when both exist and have the same identity (device
// and inode: hard links and symlinks are caught), or when neither exists and their absolute
// paths are equal once the symlinks of their existing part are resolved.
class DistinctFiles {
 public:
  // Inputs may repeat (one scene rendered twice); add every input before the outputs. Standard
  // input ("-") is no file; standard output is one, which two outputs cannot share.
  void add_input(const NamedFile& file);
  // Throws std::invalid_argument (a usage error) when `file` is the same file as one added
  // before: "--stats 'a.png' is the same file as -o 'a.png'".
  void add_output(const NamedFile& file);

 private:
  struct Key {
    bool exists = false;
    unsigned long long device = 0, inode = 0;
    std::string normal_path;  // when it does not exist
    auto operator<=>(const Key&) const = default;
  };
  static Key key_of(const std::string& path);
  std::map<Key, NamedFile> files_;
};

// The outputs against the files a scene reads, known once it is loaded (textures, glTF buffers,
// MTL files, included meshes): std::invalid_argument when an output is one of them.
void check_outputs_spare_scene_files(const std::vector<std::string>& scene_files, const std::vector<NamedFile>& outputs);

}  // namespace radiant
