#include "image/image_io.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "image/exr_header_check.h"
#include "image/packed_metadata.h"
#include "image/png_reader.h"
#include "image/png_writer.h"

namespace radiant {

namespace fs = std::filesystem;

namespace {

constexpr const char* module_file = "libradiant_oiio.so";

// Beside the running executable first, then where an installation puts it relative to the
// executable (bin/../lib/.../radiant), then, for a program inside the build tree (tests and
// benchmarks run from their own folders), where the build put it. An installed radiant never
// loads a module from a build tree.
std::vector<fs::path> module_candidates() {
  std::vector<fs::path> candidates;
  std::error_code error;
  fs::path executable = fs::read_symlink("/proc/self/exe", error);
  fs::path build = fs::path(RADIANT_MODULE_DIR);
  if (!error) {
    candidates.push_back(executable.parent_path() / module_file);
    candidates.push_back(executable.parent_path().parent_path() / RADIANT_INSTALLED_MODULE_DIR / module_file);
  }
  auto relative = executable.lexically_relative(build);
  bool in_build_tree = error || (!relative.empty() && *relative.begin() != "..");
  if (in_build_tree && (candidates.empty() || candidates.front() != build / module_file)) candidates.push_back(build / module_file);
  return candidates;
}

const ImageIoModule* load_module() {
  std::string reasons;
  for (const fs::path& candidate : module_candidates()) {
    // RTLD_LOCAL: OpenImageIO's thousands of symbols stay out of radiant's own lookups.
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      reasons += std::string(reasons.empty() ? "" : "; ") + dlerror();
      continue;
    }
    auto entry = reinterpret_cast<const ImageIoModule* (*)()>(dlsym(handle, "radiant_image_io_module"));
    const ImageIoModule* module = entry ? entry() : nullptr;
    if (module && module->interface_version == image_io_interface_version) return module;
    dlclose(handle);
    reasons += (reasons.empty() ? "" : "; ") + candidate.string() + ": built for another version of radiant";
  }
  throw std::runtime_error("cannot load radiant's OpenImageIO module " + std::string(module_file) +
                           ", needed for this image file: " + reasons);
}

}  // namespace

const ImageIoModule& image_io_module() {
  // Loaded once and never unloaded: ImageSource objects point into it.
  static const ImageIoModule* module = nullptr;
  static std::once_flag once;
  std::call_once(once, [] { module = load_module(); });
  return *module;
}

std::unique_ptr<ImageSource> open_image_file(const std::string& path, std::string& error) {
  if (is_png_file(path)) return open_png(path, error);
  // OpenEXR allocates what a header declares while opening: check the declarations first.
  if (std::string problem = exr_header_problem(path); !problem.empty()) {
    error = "corrupt OpenEXR header: " + problem;
    return nullptr;
  }
  return image_io_module().open(path, error);
}

ImageHeader read_image_header(const std::string& path) {
  std::string error;
  std::unique_ptr<ImageSource> source = open_image_file(path, error);
  if (!source) throw std::runtime_error(path + ": " + error);
  ImageHeader header = source->header();
  header.metadata = unpacked_metadata(header.metadata);
  return header;
}

void write_image_file(TemporaryFile& file, const ImageWriteSpec& spec, const void* pixels) {
  std::string error;
  if (writes_as_png(file.target(), spec)) {
    std::vector<unsigned char> bytes = encode_png(spec, static_cast<const float*>(pixels), error);
    if (error.empty()) file.write(bytes.data(), bytes.size());
  } else {
    // Only EXR keeps every attribute: other formats get them packed into their description.
    ImageWriteSpec stored = spec;
    if (lowercase_extension(file.target()) != ".exr") stored.metadata = packed_metadata(spec.metadata);
    // The temporary's name keeps the target's extension, which names the format.
    error = image_io_module().write(file.descriptor(), file.path(), stored, pixels);
    // Name the file the user asked for, not the temporary one.
    for (size_t at; (at = error.find(file.path())) != std::string::npos;) error.replace(at, file.path().size(), file.target());
  }
  if (!error.empty()) file.fail(error);
}

std::string lowercase_extension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

}  // namespace radiant
