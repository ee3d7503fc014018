#include "image/display_server.h"

#include <netdb.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "image/tev_protocol.h"

namespace radiant {

namespace {

// tev's own clients send tiles of this size: small enough that one message stays well under
// what the viewer buffers, large enough that a 4K image is a few hundred messages.
constexpr int tile_size = 128;
// A viewer that stops reading must not hold the render: a send waits at most this long.
constexpr int send_timeout_seconds = 3;

}  // namespace

DisplayServer::DisplayServer(const std::string& address) : address_(address) {
  size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == address.size())
    throw std::invalid_argument("--display-server: '" + address + "' is not HOST:PORT");
  host_ = address.substr(0, colon);
  port_ = address.substr(colon + 1);
  if (host_.size() > 2 && host_.front() == '[' && host_.back() == ']') host_ = host_.substr(1, host_.size() - 2);
  bool digits = std::all_of(port_.begin(), port_.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || port_.size() > 5 || std::stoi(port_) == 0 || std::stoi(port_) > 65535)
    throw std::invalid_argument("--display-server: port '" + port_ + "' is not a number from 1 to 65535");
}

DisplayServer::~DisplayServer() {
  if (socket_ >= 0) close(socket_);
}

void DisplayServer::fail(const std::string& reason) {
  if (socket_ >= 0) close(socket_);
  socket_ = -1;
  failed_ = true;
  warning_ = "display server " + address_ + ": " + reason + "; rendering on without it";
}

std::string DisplayServer::take_warning() {
  std::string w;
  w.swap(warning_);
  return w;
}

bool DisplayServer::send(const std::vector<uint8_t>& message) {
  size_t sent = 0;
  while (sent < message.size()) {
    // MSG_NOSIGNAL: a viewer that went away is an error here, not a SIGPIPE that ends radiant.
    ssize_t n = ::send(socket_, message.data() + sent, message.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      fail(n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) ? "the viewer stopped reading" : std::strerror(errno));
      return false;
    }
    sent += size_t(n);
  }
  return true;
}

bool DisplayServer::show(const std::string& name, const OutputImage& image) {
  if (failed_) return false;
  if (socket_ < 0) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (int err = getaddrinfo(host_.c_str(), port_.c_str(), &hints, &found)) {
      fail(gai_strerror(err));
      return false;
    }
    std::string reason = "no address";
    for (addrinfo* a = found; a && socket_ < 0; a = a->ai_next) {
      int s = socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
      if (s < 0) continue;
      timeval timeout{send_timeout_seconds, 0};
      setsockopt(s, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
      if (connect(s, a->ai_addr, a->ai_addrlen) == 0) {
        socket_ = s;
      } else {
        reason = std::strerror(errno);
        close(s);
      }
    }
    freeaddrinfo(found);
    if (socket_ < 0) {
      fail(reason);
      return false;
    }
  }
  auto it = std::find_if(shown_.begin(), shown_.end(), [&](const Shown& s) { return s.name == name; });
  bool same_shape = it != shown_.end() && it->width == image.width && it->height == image.height &&
                    it->channels == image.channels;
  if (!same_shape) {
    if (it != shown_.end()) {
      if (!send(tev_close_image(name))) return false;
      shown_.erase(it);
    }
    if (!send(tev_create_image(name, image.width, image.height, image.channels))) return false;
    shown_.push_back({name, image.width, image.height, image.channels});
  }
  size_t channel_count = image.channels.size();
  std::vector<float> tile;
  for (int y0 = 0; y0 < image.height; y0 += tile_size)
    for (int x0 = 0; x0 < image.width; x0 += tile_size) {
      int w = std::min(tile_size, image.width - x0), h = std::min(tile_size, image.height - y0);
      tile.resize(size_t(w) * size_t(h));
      for (size_t c = 0; c < channel_count; ++c) {
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            tile[size_t(y) * w + x] = image.pixels[(size_t(y0 + y) * image.width + (x0 + x)) * channel_count + c];
        if (!send(tev_update_image(name, image.channels[c], x0, y0, w, h, tile.data()))) return false;
      }
    }
  return true;
}

}  // namespace radiant
