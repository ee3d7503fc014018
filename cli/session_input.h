// Where a session's command lines come from: standard input, and with --serve also the page.
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>

namespace radiant::cli {

class SessionInput {
 public:
  // Without `with_page` lines are read from standard input as they are asked for; with it a
  // thread reads them, the page adds its own, and the end of standard input no longer ends the
  // session (`quit`, typed or sent, does).
  explicit SessionInput(bool with_page);
  // The next line, true; false at the end of the input. Throws std::invalid_argument for a line
  // that standard input could not give (radiant's line limits, docs/cli.md).
  bool next(std::string& text);
  // A line the page sent.
  void push(const std::string& text);

 private:
  struct Line {
    std::string text;
    bool failed = false;  // text is the reason
  };
  struct Queue {
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<Line> lines;
  };
  bool with_page_;
  // Shared with the reader thread, which may outlive the session while blocked on a read.
  std::shared_ptr<Queue> queue_;
};

}  // namespace radiant::cli
