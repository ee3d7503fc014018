// A stand-in for the tev viewer: listens on a free loopback port, takes one connection at a time
// and keeps every message radiant sends, decoded, until the sender closes.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace radiant::test {

struct TevMessageRead {
  uint8_t type = 0;
  bool grab_focus = false;
  std::string name, channel;            // channel: update messages
  int x = 0, y = 0, width = 0, height = 0;
  std::vector<std::string> channels;    // create messages
  std::vector<float> values;            // update messages
};

class TevListener {
 public:
  TevListener();  // listens at once; port() is known from here on
  ~TevListener();
  int port() const { return port_; }
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  // Call once radiant has exited: stops listening and returns what every connection sent, in
  // order; a message that does not parse fails the test.
  std::vector<TevMessageRead> messages();

 private:
  int listener_ = -1, port_ = 0;
  std::thread reader_;
  std::vector<uint8_t> bytes_;
  std::atomic<bool> done_ = false;
};

}  // namespace radiant::test
