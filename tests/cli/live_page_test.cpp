// The --serve page's server: its own routes and nothing else, request sizes and rates capped,
// and a slow or hostile client that does not keep it from answering others.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <doctest/doctest.h>
#include <httplib.h>

#include <atomic>
#include <stdexcept>
#include <string>

#include "live_page.h"

using namespace radiant;
using namespace radiant::cli;

namespace {

OutputImage gray_image(float value) {
  OutputImage image;
  image.width = 4;
  image.height = 2;
  image.channels = {"R", "G", "B"};
  image.pixels.assign(4 * 2 * 3, value);
  return image;
}

// Sends `request` as raw bytes and returns what comes back before the server closes or 2 s pass.
std::string raw_exchange(int port, const std::string& request) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  timeval timeout{2, 0};
  setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  for (size_t sent = 0; sent < request.size();) {
    ssize_t n = send(s, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;  // the server may close on an oversized request before reading it all
    sent += size_t(n);
  }
  std::string answer;
  char buffer[4096];
  for (ssize_t n; (n = recv(s, buffer, sizeof buffer, 0)) > 0;) answer.append(buffer, size_t(n));
  close(s);
  return answer;
}

}  // namespace

TEST_CASE("live page serves its page, status and image, and nothing else") {
  LivePage page("127.0.0.1:0", {});
  httplib::Client client("127.0.0.1", page.port());
  auto root = client.Get("/");
  REQUIRE(root);
  CHECK(root->status == 200);
  CHECK(root->body.find("<img id=\"image\"") != std::string::npos);
  auto status = client.Get("/status");
  REQUIRE(status);
  CHECK(status->body.find("\"generation\": 0") != std::string::npos);
  CHECK(status->body.find("\"commands\": false") != std::string::npos);
  auto none = client.Get("/image.png");
  REQUIRE(none);
  CHECK(none->status == 404);

  page.show("out \"1\".png", gray_image(0.5f), 2, 8, 1.0);
  auto image = client.Get("/image.png");
  REQUIRE(image);
  CHECK(image->status == 200);
  CHECK(image->body.substr(1, 3) == "PNG");
  status = client.Get("/status");
  REQUIRE(status);
  CHECK(status->body.find("\"generation\": 1") != std::string::npos);
  CHECK(status->body.find("\"name\": \"out \\\"1\\\".png\"") != std::string::npos);  // JSON-escaped
  CHECK(status->body.find("\"eta\": 3.000") != std::string::npos);  // 2 of 8 samples took 1 s

  for (const char* path : {"/../../etc/passwd", "/etc/passwd", "/image.png/../../x", "/favicon.ico", "/status/x"}) {
    CAPTURE(path);
    auto r = client.Get(path);
    REQUIRE(r);
    CHECK(r->status == 404);
  }
  auto command = client.Post("/command", "turn 0 10 0", "text/plain");
  REQUIRE(command);
  CHECK(command->status == 404);  // a render's page takes no commands
}

TEST_CASE("live page passes one-line commands on and refuses the rest") {
  std::vector<std::string> taken;
  LivePage page("0", [&](const std::string& line) { taken.push_back(line); });
  httplib::Client client("127.0.0.1", page.port());
  auto ok = client.Post("/command", "turn 0 10 0", "text/plain");
  REQUIRE(ok);
  CHECK(ok->status == 200);
  auto two_lines = client.Post("/command", "turn 0 10 0\nquit", "text/plain");
  REQUIRE(two_lines);
  CHECK(two_lines->status == 400);
  auto huge = client.Post("/command", std::string(64 * 1024, 'x'), "text/plain");
  REQUIRE(huge);
  CHECK(huge->status == 413);
  CHECK(taken == std::vector<std::string>{"turn 0 10 0"});
}

TEST_CASE("live page survives huge headers, slow clients and floods") {
  LivePage page("127.0.0.1:0", {});
  int port = page.port();
  std::string huge_header = "GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(1 << 20, 'a') + "\r\n\r\n";
  CHECK(raw_exchange(port, huge_header).find("200 OK") == std::string::npos);

  // A client that sends half a request and waits: the others are still answered.
  int slow = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(connect(slow, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  CHECK(send(slow, "GET / HTTP/1.1\r\nHo", 18, MSG_NOSIGNAL) == 18);
  CHECK(raw_exchange(port, "GET /status HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n").find("200 OK") !=
        std::string::npos);
  close(slow);

  httplib::Client client("127.0.0.1", port);
  bool refused = false;  // past 100 requests in a second
  for (int i = 0; i < 5000 && !refused; ++i)
    if (auto r = client.Get("/status"); r && r->status == 429) refused = true;
  CHECK(refused);
}

TEST_CASE("live page refuses addresses that are not PORT or HOST:PORT") {
  for (const char* bad : {"", "http", "127.0.0.1:", ":80", "127.0.0.1:99999"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(LivePage(bad, {}), std::invalid_argument);
  }
}
