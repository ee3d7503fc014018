#include "live_page.h"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "live_page_html.h"

namespace radiant::cli {

namespace {

// A command is one line; the largest a session takes (a `render` with a long path) fits easily.
constexpr size_t max_command_bytes = 4096;
// A client that sends or reads nothing for this long is dropped, so slow clients cannot pile up.
constexpr time_t socket_timeout_seconds = 5;

std::string json_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else out += c;
  }
  return out;
}

}  // namespace

struct LivePage::State {
  httplib::Server server;
  std::thread thread;
  std::string host;
  int port = 0;
  std::function<void(const std::string&)> on_command;

  std::mutex mutex;  // guards what follows
  std::string name = "radiant", state = "waiting";
  std::shared_ptr<const std::vector<unsigned char>> png;
  uint64_t generation = 0;
  uint32_t samples = 0, target = 0;
  double elapsed = 0, eta = -1;
  std::chrono::steady_clock::time_point window_start = std::chrono::steady_clock::now();
  int requests_in_window = 0, requests_per_second = 0;

  // False when the last second has seen too many requests.
  bool admit() {
    std::lock_guard lock(mutex);
    auto now = std::chrono::steady_clock::now();
    if (now - window_start >= std::chrono::seconds(1)) window_start = now, requests_in_window = 0;
    return ++requests_in_window <= requests_per_second;
  }
};

LivePage::LivePage(const std::string& address, std::function<void(const std::string&)> on_command,
                   int requests_per_second)
    : state_(std::make_unique<State>()) {
  std::string host = "127.0.0.1", port_text = address;
  if (size_t colon = address.rfind(':'); colon != std::string::npos) {
    host = address.substr(0, colon);
    port_text = address.substr(colon + 1);
    if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  }
  bool digits = !port_text.empty() && port_text.size() <= 5 &&
                std::all_of(port_text.begin(), port_text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (host.empty() || !digits || std::stoi(port_text) > 65535)
    throw std::invalid_argument("--serve: '" + address + "' is not PORT or HOST:PORT");
  State& s = *state_;
  s.host = host;
  s.requests_per_second = requests_per_second;
  s.on_command = std::move(on_command);
  s.server.set_payload_max_length(max_command_bytes);
  s.server.set_read_timeout(socket_timeout_seconds, 0);
  s.server.set_write_timeout(socket_timeout_seconds, 0);
  s.server.set_keep_alive_max_count(100);
  s.server.set_pre_routing_handler([&s](const httplib::Request&, httplib::Response& res) {
    if (s.admit()) return httplib::Server::HandlerResponse::Unhandled;
    res.status = 429;
    res.set_content("too many requests\n", "text/plain");
    return httplib::Server::HandlerResponse::Handled;
  });
  s.server.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(live_page_html, "text/html; charset=utf-8");
  });
  s.server.Get("/status", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    char numbers[256];
    std::snprintf(numbers, sizeof numbers,
                  "\"generation\": %llu, \"samples\": %u, \"target\": %u, \"elapsed\": %.3f, \"eta\": %.3f",
                  static_cast<unsigned long long>(s.generation), s.samples, s.target, s.elapsed, s.eta);
    res.set_header("Cache-Control", "no-store");
    res.set_content(std::string("{\"name\": \"") + json_escaped(s.name) + "\", \"state\": \"" + s.state + "\", " +
                        numbers + ", \"commands\": " + (s.on_command ? "true" : "false") + "}",
                    "application/json");
  });
  s.server.Get("/image.png", [&s](const httplib::Request&, httplib::Response& res) {
    std::shared_ptr<const std::vector<unsigned char>> png;
    {
      std::lock_guard lock(s.mutex);
      png = s.png;
    }
    if (!png) {
      res.status = 404;
      res.set_content("no image yet\n", "text/plain");
      return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(reinterpret_cast<const char*>(png->data()), png->size(), "image/png");
  });
  s.server.Post("/command", [&s](const httplib::Request& req, httplib::Response& res) {
    if (!s.on_command) {
      res.status = 404;
      res.set_content("this page takes no commands (only a session's does)\n", "text/plain");
      return;
    }
    if (req.body.find_first_of("\r\n") != std::string::npos || req.body.find('\0') != std::string::npos) {
      res.status = 400;
      res.set_content("one command per request, on one line\n", "text/plain");
      return;
    }
    s.on_command(req.body);
    res.set_content("taken\n", "text/plain");
  });
  s.port = port_text == "0" ? s.server.bind_to_any_port(host) : (s.server.bind_to_port(host, std::stoi(port_text))
                                                                     ? std::stoi(port_text)
                                                                     : -1);
  if (s.port <= 0) throw std::runtime_error("--serve: cannot listen on " + address);
  s.thread = std::thread([&s] { s.server.listen_after_bind(); });
  // stop() does nothing before the server runs: a page stopped that early would never end its
  // thread. Wait for it (it runs within microseconds).
  for (int waited = 0; !s.server.is_running() && waited < 5000; ++waited)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

LivePage::~LivePage() {
  state_->server.stop();
  if (state_->thread.joinable()) state_->thread.join();
}

int LivePage::port() const { return state_->port; }

std::string LivePage::url() const {
  const std::string& h = state_->host;
  return "http://" + (h.find(':') != std::string::npos ? "[" + h + "]" : h) + ":" + std::to_string(state_->port) + "/";
}

void LivePage::show(const std::string& name, const OutputImage& image, uint32_t samples, uint32_t target,
                    double elapsed) {
  std::string error;
  auto png = std::make_shared<const std::vector<unsigned char>>(encode_preview_png(image, error));
  std::lock_guard lock(state_->mutex);
  State& s = *state_;
  if (!png->empty()) s.png = std::move(png), ++s.generation;
  s.name = name;
  s.state = "rendering";
  s.samples = samples;
  s.target = target;
  s.elapsed = elapsed;
  // Samples cost about the same throughout: the rest takes what the done ones took, in proportion.
  s.eta = samples > 0 ? elapsed * (double(target) / samples - 1.0) : -1;
}

void LivePage::finished() {
  std::lock_guard lock(state_->mutex);
  state_->state = "done";
  state_->eta = 0;
}

std::unique_ptr<LivePage> make_live_page(const std::string& address, std::function<void(const std::string&)> on_command) {
  if (address.empty()) return nullptr;
  return std::make_unique<LivePage>(address, std::move(on_command));
}

}  // namespace radiant::cli
