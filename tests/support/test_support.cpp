#include "support/test_support.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "commands.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "output/output_set.h"

namespace radiant::test {

namespace fs = std::filesystem;

ScratchDir::ScratchDir(const std::string& tag) {
  static std::atomic<int> counter{0};
  path = fs::temp_directory_path() /
         ("radiant-test-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(path);
  fs::create_directories(path);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path, ec);
}

fs::path ScratchDir::write(const std::string& name, const std::string& text) const {
  fs::path p = path / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string ScratchDir::without_path(std::string text) const {
  std::string folder = path.string() + "/";
  for (size_t at; (at = text.find(folder)) != std::string::npos;) text.erase(at, folder.size());
  return text;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

CommandResult run_radiant(const std::string& args, const std::string& stdin_text,
                          int timeout_seconds) {
  ScratchDir io("cmd");
  fs::path in = io.write("stdin.txt", stdin_text);
  fs::path out = io.file("stdout.txt"), err = io.file("stderr.txt");
  std::string cmd = "timeout " + std::to_string(timeout_seconds) + " " RADIANT_EXE " " + args +
                    " <'" + in.string() + "' >'" + out.string() + "' 2>'" + err.string() + "'";
  int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_bytes(out);
  r.err = read_bytes(err);
  return r;
}

CommandResult run_radiant_in_process(const std::vector<std::string>& words) {
  std::vector<std::string> arguments = words;
  std::vector<char*> argv;
  for (std::string& word : arguments) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::ostringstream err;
  struct RestoreCerr {
    std::streambuf* saved;
    ~RestoreCerr() { std::cerr.rdbuf(saved); }
  } restore{std::cerr.rdbuf(err.rdbuf())};
  CommandResult result;
  for (const cli::Command& command : cli::commands())
    if (!words.empty() && words[0] == command.name) result.exit_code = command.run(int(words.size()), argv.data());
  result.err = err.str();
  return result;
}

MeasuredRun run_radiant_measured(const std::string& args, int timeout_seconds, uint64_t address_space_limit) {
  ScratchDir io("measured");
  fs::path out = io.file("stdout.txt"), err = io.file("stderr.txt");
  // The shell execs radiant in place, so the child whose rusage wait4 reports is radiant itself.
  std::string command = "exec " RADIANT_EXE " " + args + " </dev/null >'" + out.string() + "' 2>'" + err.string() + "'";
  pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    if (address_space_limit > 0) {
      rlimit limit{rlim_t(address_space_limit), rlim_t(address_space_limit)};
      setrlimit(RLIMIT_AS, &limit);
    }
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
  int status = 0;
  rusage usage{};
  while (wait4(child, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(child, SIGKILL);
      wait4(child, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  MeasuredRun run;
  run.result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.result.out = read_bytes(out);
  run.result.err = read_bytes(err);
  run.peak_rss_bytes = uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
  return run;
}

TestImage read_image(const fs::path& file) {
  std::string error;
  auto input = open_image_file(file.string(), error, nullptr);
  if (!input) throw std::runtime_error("cannot open image " + file.string() + ": " + error);
  const ImageHeader& header = input->header();
  TestImage img;
  img.width = header.width;
  img.height = header.height;
  img.channels = header.channels;
  img.channel_names = header.channel_names;
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  if (!input->read(img.channels, PixelType::float32, img.pixels.data()))
    throw std::runtime_error("cannot read image " + file.string() + ": " + input->error());
  return img;
}

bool same_pixels(const fs::path& a, const fs::path& b) {
  TestImage first = read_image(a), second = read_image(b);
  return first.width == second.width && first.height == second.height && first.channel_names == second.channel_names &&
         first.pixels.size() == second.pixels.size() &&
         std::memcmp(first.pixels.data(), second.pixels.data(), first.pixels.size() * sizeof(float)) == 0;
}

std::string image_attribute(const fs::path& file, const std::string& name) {
  return find_attribute(read_image_header(file.string(), nullptr).metadata, name).value_or("");
}

void write_test_image(const fs::path& path, int width, int height, const std::vector<std::string>& names,
                      const std::vector<float>& values) {
  ImageWriteSpec spec;
  spec.width = width;
  spec.height = height;
  spec.channel_names = names;
  spec.type = lowercase_extension(path.string()) == ".exr" ? PixelType::float32 : PixelType::uint8;
  OutputSet outputs;
  write_image_file(outputs.create(path.string()), spec, values.data());
  outputs.commit();
}

void write_texel_bytes(const fs::path& path, int width, int height, int channels,
                       const std::vector<unsigned char>& texels) {
  std::vector<float> values(texels.begin(), texels.end());
  for (float& v : values) v /= 255;  // quantized back to exactly these bytes
  std::vector<std::string> names = channels == 1   ? std::vector<std::string>{"Y"}
                                   : channels == 4 ? std::vector<std::string>{"R", "G", "B", "A"}
                                                   : std::vector<std::string>{"R", "G", "B"};
  write_test_image(path, width, height, names, values);
}

fs::path source_path(const std::string& relative) { return fs::path(RADIANT_SOURCE_DIR) / relative; }

}  // namespace radiant::test
