#include "support/test_support.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

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

TestImage read_image(const fs::path& file) {
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) throw std::runtime_error("cannot open image " + file.string());
  const OIIO::ImageSpec& spec = input->spec();
  TestImage img;
  img.width = spec.width;
  img.height = spec.height;
  img.channels = spec.nchannels;
  img.channel_names = spec.channelnames;
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  if (!input->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
    throw std::runtime_error("cannot read image " + file.string());
  return img;
}

fs::path source_path(const std::string& relative) { return fs::path(RADIANT_SOURCE_DIR) / relative; }

}  // namespace radiant::test
