#include "image/image_io.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "image/exr_header_check.h"
#include "image/exr_writer.h"
#include "image/image_format.h"
#include "image/hdr_header.h"
#include "image/packed_metadata.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "memory/input_file.h"

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

namespace {

// A source and the memory its decoding holds.
class ChargedImageSource final : public ImageSource {
 public:
  ChargedImageSource(std::unique_ptr<ImageSource> source, MemoryCharge decoder, MemoryCharge copy)
      : source_(std::move(source)), decoder_(std::move(decoder)), copy_(std::move(copy)) {}
  const ImageHeader& header() const override { return source_->header(); }
  bool read(int channels, PixelType type, void* out) override { return source_->read(channels, type, out); }
  bool read_channels(int begin, int end, PixelType type, void* out) override {
    return source_->read_channels(begin, end, type, out);
  }
  std::string error() override { return source_->error(); }

 private:
  std::unique_ptr<ImageSource> source_;
  MemoryCharge decoder_, copy_;
};

}  // namespace

std::unique_ptr<ImageSource> open_image_file(const std::string& path, std::string& error, MemoryBudget* budget) {
  // Checked before anything opens it: a FIFO or a device would block or never end.
  uint64_t size = 0;
  if (std::string problem = input_file_problem(path, size); !problem.empty()) {
    error = problem;
    return nullptr;
  }
  MemoryCharge decoder;
  std::unique_ptr<ImageSource> source;
  if (is_png_file(path)) {
    source = open_png(path, error);
  } else {
    // OpenEXR allocates what a header declares while opening: check the declarations first.
    ExrHeaderCheck exr = check_exr_header(path);
    if (!exr.problem.empty()) {
      error = "corrupt OpenEXR header: " + exr.problem;
      return nullptr;
    }
    decoder = MemoryCharge(budget, exr.decoder_bytes, path + ": OpenEXR's buffers for its declared chunks");
    source = image_io_module().open(path, error);
  }
  if (!source) return nullptr;
  const ImageHeader& header = source->header();
  // Four bytes a value, and a row pointer a row (libpng's).
  uint64_t rows = saturating_multiply(uint64_t(std::max(header.height, 0)), uint64_t(std::max(header.depth, 1)));
  uint64_t values = saturating_multiply(saturating_multiply(rows, uint64_t(std::max(header.width, 0))),
                                        uint64_t(std::max(header.channels, 0)));
  MemoryCharge copy(budget, saturating_add(saturating_multiply(values, 4), saturating_multiply(rows, 8)),
                    path + ": decoding its " + std::to_string(header.width) + "x" + std::to_string(header.height) + " pixels");
  return std::make_unique<ChargedImageSource>(std::move(source), std::move(decoder), std::move(copy));
}

ImageHeader read_image_header(const std::string& path, MemoryBudget* budget) {
  std::string error;
  std::unique_ptr<ImageSource> source = open_image_file(path, error, budget);
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
  } else if (writes_as_exr(file.target(), spec)) {
    error = write_exr(file, spec, pixels);
  } else {
    // Only EXR keeps every attribute: other formats get them packed into their description.
    ImageWriteSpec stored = spec;
    if (!image_format_of(file.target()).header_metadata) stored.metadata = packed_metadata(spec.metadata);
    // The temporary's name keeps the target's extension, which names the format.
    error = image_io_module().write(file.descriptor(), file.path(), stored, pixels);
    if (error.empty() && image_format_of(file.target()).radiance_header) add_hdr_header_lines(file, spec.metadata);
    // Name the file the user asked for, not the temporary one.
    for (size_t at; (at = error.find(file.path())) != std::string::npos;) error.replace(at, file.path().size(), file.target());
  }
  if (!error.empty()) file.fail(error);
}

}  // namespace radiant
