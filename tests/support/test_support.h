// Helpers shared by tests: scratch folders, running the CLI, reading rendered images.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace radiant::test {

// A fresh, empty folder under the system temp dir, removed when the object dies.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& tag);
  ~ScratchDir();
  std::filesystem::path file(const std::string& name) const { return path / name; }
  // Writes `text` to `name` inside the folder and returns the full path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;
  // `text` with this folder's path (and the separator after it) removed wherever it appears, so
  // messages can be compared whatever the folder is called.
  std::string without_path(std::string text) const;
};

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `radiant ARGS` (the built executable) with a hard timeout in seconds; `stdin_text` is fed
// to its standard input.
CommandResult run_radiant(const std::string& args, const std::string& stdin_text = "",
                          int timeout_seconds = 120);

// Runs the command `words[0]` of radiant (render, merge, ...) with the words after it in this
// process, through the same function cli/main.cpp calls, with its standard error captured. For
// tests of many tiny runs, where a child process each (and loading OpenImageIO's ~265 libraries,
// a quarter second) would be most of the test's time; what only a process shows (exit codes at
// the shell, signals, files left behind) stays with run_radiant.
CommandResult run_radiant_in_process(const std::vector<std::string>& words);

// A run of radiant in a child process of its own, with that child's peak resident memory.
struct MeasuredRun {
  CommandResult result;
  uint64_t peak_rss_bytes = 0;  // wait4's ru_maxrss
};
// Runs `radiant ARGS` like run_radiant (exit_code -1 when killed, by the timeout or a signal).
// `address_space_limit` > 0 caps the child's virtual memory (RLIMIT_AS), so that a regression
// fails the test instead of exhausting the machine (not under AddressSanitizer, whose shadow
// memory needs terabytes of address space).
MeasuredRun run_radiant_measured(const std::string& args, int timeout_seconds = 120,
                                 uint64_t address_space_limit = 0);

// True in the AddressSanitizer builds, where resident memory measures the sanitizer's bookkeeping
// and RLIMIT_AS cannot be used. GCC defines __SANITIZE_ADDRESS__; clang 14 only answers
// __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define RADIANT_TESTS_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RADIANT_TESTS_UNDER_ASAN 1
#endif
#endif
#if defined(RADIANT_TESTS_UNDER_ASAN)
constexpr bool built_with_address_sanitizer = true;
#else
constexpr bool built_with_address_sanitizer = false;
#endif

// A float image as read through the OpenImageIO module (all channels, row-major, top row first).
struct TestImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
  std::vector<std::string> channel_names;
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};
TestImage read_image(const std::filesystem::path& file);

// Writes a test image through radiant's own image I/O: float `values` (width*height*names.size(),
// row-major) with those channel names, stored as float in EXR and as 8 bits otherwise.
void write_test_image(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::string>& names, const std::vector<float>& values);
// An 8-bit image (a texture) with exactly these texel bytes, 1 (gray) or 3 (RGB) channels.
void write_texel_bytes(const std::filesystem::path& path, int width, int height, int channels,
                       const std::vector<unsigned char>& texels);

// Whole file contents as bytes, for byte-identity checks.
std::string read_bytes(const std::filesystem::path& file);

// Whether two image files hold the same pixels: size, channel names and every value, bit for
// bit. Renders record how they were made (times, command lines), so their bytes differ where
// their pixels do not.
bool same_pixels(const std::filesystem::path& a, const std::filesystem::path& b);

// The metadata attribute `name` of the image at `file` (as read_image_header unpacks it), or ""
// when it has none.
std::string image_attribute(const std::filesystem::path& file, const std::string& name);

// A path as one shell word, for run_radiant's command lines.
inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// Absolute path of a file in the source tree (e.g. "assets/cornell.gltf").
std::filesystem::path source_path(const std::string& relative);

}  // namespace radiant::test
