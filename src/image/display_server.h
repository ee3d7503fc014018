// Streams images to a running tev viewer (--display-server HOST:PORT) as a render converges.
// The viewer is a convenience: a refused or dropped connection is one warning, after which the
// render goes on without it.
#pragma once

#include <string>
#include <vector>

#include "image/image_writer.h"

namespace radiant {

class DisplayServer {
 public:
  // `address` is HOST:PORT (a name, IPv4 or [IPv6] host); std::invalid_argument when it is not.
  explicit DisplayServer(const std::string& address);
  ~DisplayServer();
  DisplayServer(const DisplayServer&) = delete;
  DisplayServer& operator=(const DisplayServer&) = delete;

  // Shows `image` (linear floats) under `name`: the first call for a name opens the image in the
  // viewer, later ones replace its pixels; a name shown at another size or with other channels
  // is opened anew. Connects on first use; returns false (and no more tries) once the connection
  // failed, with the reason in take_warning().
  bool show(const std::string& name, const OutputImage& image);
  // Takes back the warning to print, once: "" when there is none (yet).
  std::string take_warning();

 private:
  bool send(const std::vector<uint8_t>& message);
  void fail(const std::string& reason);

  std::string address_, host_, port_;
  int socket_ = -1;
  bool failed_ = false;
  std::string warning_;
  struct Shown {
    std::string name;
    int width, height;
    std::vector<std::string> channels;
  };
  std::vector<Shown> shown_;
};

}  // namespace radiant
