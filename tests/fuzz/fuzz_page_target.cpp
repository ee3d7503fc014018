// The page target: the bytes as one client's raw request stream to a live page (--serve) on
// loopback, the way a hostile browser or script would send them; the page must answer or close
// and go on serving. One page serves every input, as one page serves a session's clients.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <stdexcept>

#include "fuzz_support.h"
#include "live_page.h"

namespace radiant::fuzz {

FuzzOutcome run_page_target(const std::filesystem::path&, const std::string& bytes) {
  static std::atomic<int> commands{0};
  static cli::LivePage page("127.0.0.1:0", [](const std::string&) { ++commands; }, 1 << 30);
  static const bool shown = [] {
    OutputImage image;
    image.width = image.height = 2;
    image.channels = {"R", "G", "B"};
    image.pixels.assign(12, 0.5f);
    page.show("fuzz.png", image, 1, 4, 0.1);
    return true;
  }();
  (void)shown;
  return outcome_of([&] {
    int s = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (s < 0) throw std::runtime_error("page target: no socket");
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(page.port()));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      close(s);
      throw std::runtime_error("page target: the page stopped listening");
    }
    timeval timeout{2, 0};
    setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    for (size_t sent = 0; sent < bytes.size();) {
      ssize_t n = send(s, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;  // the page may close on a bad request before reading it all
      sent += size_t(n);
    }
    shutdown(s, SHUT_WR);  // the end of the request stream: the page answers what it has
    char buffer[4096];
    while (recv(s, buffer, sizeof buffer, 0) > 0) {
    }
    close(s);
  });
}

}  // namespace radiant::fuzz
