#include "file_access.h"

#include <fstream>

#include "load_options.h"
#include "message_text.h"
#include "memory/input_file.h"

namespace radiant {

namespace fs = std::filesystem;

// True when `path` (both sides canonical) lies inside `folder`.
static bool is_inside(const fs::path& folder, const fs::path& path) {
  auto f = folder.begin(), p = path.begin();
  for (; f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // trailing separator of the folder
    if (p == path.end() || *f != *p) return false;
  }
  return true;
}

fs::path resolve_inside(const fs::path& base_dir, const std::string& uri, bool allow_external,
                        const std::string& where) {
  if (uri.empty()) throw LoadError(where + ": empty file name");
  if (uri.find('\0') != std::string::npos) throw LoadError(where + ": file name contains a NUL byte");
  fs::path relative(uri);
  if (allow_external) return (relative.is_absolute() ? relative : base_dir / relative).lexically_normal();
  const std::string hint = " (use --allow-external-files to allow it)";
  if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
    throw LoadError(where + ": '" + escaped(uri) + "' is an absolute path" + hint);
  fs::path normal = relative.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..")
    throw LoadError(where + ": '" + escaped(uri) + "' leaves the scene's folder" + hint);
  // Symlinks may still lead outside: compare the real locations.
  std::error_code ec;
  fs::path real_base = fs::weakly_canonical(fs::absolute(base_dir), ec);
  fs::path real_file = fs::weakly_canonical(fs::absolute(base_dir / normal), ec);
  if (ec || !is_inside(real_base, real_file))
    throw LoadError(where + ": '" + escaped(uri) + "' leads outside the scene's folder through a symlink" + hint);
  return real_file;
}

uint64_t check_input_file(const fs::path& path, const std::string& label, const LoadOptions& options) {
  uint64_t size = 0;
  std::string problem = input_file_problem(path, size);
  if (!problem.empty()) throw LoadError(label + ": " + problem);
  if (options.files_read) options.files_read->push_back(path.string());
  return size;
}

std::string read_input_file(const fs::path& path, const std::string& label, const LoadOptions& options) {
  uint64_t size = check_input_file(path, label, options);
  charge_load(options, size, label);
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in || !in.read(bytes.data(), std::streamsize(size))) throw LoadError(label + ": read failed");
  return bytes;
}

}  // namespace radiant
