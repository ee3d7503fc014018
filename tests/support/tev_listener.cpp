#include "support/tev_listener.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include <cstring>
#include <stdexcept>

namespace radiant::test {

TevListener::TevListener() {
  listener_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;  // any free port
  socklen_t size = sizeof address;
  if (listener_ < 0 || bind(listener_, reinterpret_cast<sockaddr*>(&address), size) != 0 || listen(listener_, 4) != 0 ||
      getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size) != 0)
    throw std::runtime_error("tev listener: cannot listen on loopback");
  port_ = ntohs(address.sin_port);
  // Reads connections one after another until none comes for the wait messages() allows.
  reader_ = std::thread([this] {
    for (;;) {
      pollfd p{listener_, POLLIN, 0};
      if (poll(&p, 1, 200) <= 0) {
        if (done_) return;
        continue;
      }
      int connection = accept(listener_, nullptr, nullptr);
      if (connection < 0) return;
      uint8_t buffer[1 << 16];
      for (ssize_t n; (n = read(connection, buffer, sizeof buffer)) > 0;) bytes_.insert(bytes_.end(), buffer, buffer + n);
      close(connection);
    }
  });
}

TevListener::~TevListener() {
  done_ = true;
  if (reader_.joinable()) reader_.join();
  if (listener_ >= 0) close(listener_);
}

std::vector<TevMessageRead> TevListener::messages() {
  done_ = true;
  if (reader_.joinable()) reader_.join();
  std::vector<TevMessageRead> out;
  size_t at = 0;
  auto take = [&](void* to, size_t size, size_t end) {
    REQUIRE(at + size <= end);
    std::memcpy(to, bytes_.data() + at, size);
    at += size;
  };
  auto text = [&](size_t end) {
    std::string s;
    while (at < end && bytes_[at] != 0) s += char(bytes_[at++]);
    REQUIRE(at < end);
    ++at;
    return s;
  };
  while (at < bytes_.size()) {
    uint32_t length = 0;
    size_t start = at;
    take(&length, 4, bytes_.size());
    REQUIRE(length >= 5);
    size_t end = start + length;
    REQUIRE(end <= bytes_.size());
    TevMessageRead m;
    take(&m.type, 1, end);
    if (m.type == 2) {
      m.name = text(end);
    } else {
      uint8_t focus = 0;
      take(&focus, 1, end);
      m.grab_focus = focus != 0;
      m.name = text(end);
      if (m.type == 4) {
        int32_t count = 0;
        take(&m.width, 4, end);
        take(&m.height, 4, end);
        take(&count, 4, end);
        for (int32_t i = 0; i < count; ++i) m.channels.push_back(text(end));
      } else {
        REQUIRE(m.type == 3);
        m.channel = text(end);
        take(&m.x, 4, end);
        take(&m.y, 4, end);
        take(&m.width, 4, end);
        take(&m.height, 4, end);
        m.values.resize(size_t(m.width) * size_t(m.height));
        take(m.values.data(), m.values.size() * sizeof(float), end);
      }
    }
    REQUIRE(at == end);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace radiant::test
