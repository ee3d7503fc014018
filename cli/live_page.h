// --serve [HOST:]PORT: a small web page that shows a render as it converges and, in a session,
// takes the session's commands (docs/cli.md, "Watching a render"). It serves only its own page,
// image and status, reads no file a request names, caps request sizes and rates, and never holds
// up the render: a pass hands it an image and goes on.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "image/image_writer.h"

namespace radiant::cli {

class LivePage {
 public:
  // Listens on `address`: "PORT" binds to 127.0.0.1, "HOST:PORT" to that host (0 picks a free
  // port). std::invalid_argument for an address that is not one, std::runtime_error when it
  // cannot be bound. With `on_command`, the page offers a command line whose lines go there.
  LivePage(const std::string& address, std::function<void(const std::string&)> on_command);
  ~LivePage();
  LivePage(const LivePage&) = delete;
  LivePage& operator=(const LivePage&) = delete;

  int port() const;
  std::string url() const;  // http://HOST:PORT/
  // The image after a pass: `samples` of `target` per pixel, `elapsed` seconds into the render.
  void show(const std::string& name, const OutputImage& image, uint32_t samples, uint32_t target, double elapsed);
  // The render of the last image shown has finished (or was stopped).
  void finished();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The connection for `address`, or null when --serve was not given.
std::unique_ptr<LivePage> make_live_page(const std::string& address,
                                         std::function<void(const std::string&)> on_command = {});

}  // namespace radiant::cli
