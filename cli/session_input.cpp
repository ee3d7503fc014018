#include "session_input.h"

#include <iostream>
#include <stdexcept>
#include <thread>

#include "render_line.h"

namespace radiant::cli {

SessionInput::SessionInput(bool with_page) : with_page_(with_page), queue_(std::make_shared<Queue>()) {
  if (!with_page_) return;
  // Detached: at `quit` the process leaves while the thread may still wait for a line.
  std::thread([queue = queue_] {
    for (;;) {
      Line line;
      try {
        if (!read_command_line(std::cin, line.text)) return;
      } catch (const std::invalid_argument& e) {
        line = {e.what(), true};
      }
      std::lock_guard lock(queue->mutex);
      queue->lines.push_back(std::move(line));
      queue->ready.notify_one();
    }
  }).detach();
}

bool SessionInput::next(std::string& text) {
  if (!with_page_) return read_command_line(std::cin, text);
  std::unique_lock lock(queue_->mutex);
  queue_->ready.wait(lock, [&] { return !queue_->lines.empty(); });
  Line line = std::move(queue_->lines.front());
  queue_->lines.pop_front();
  if (line.failed) throw std::invalid_argument(line.text);
  text = std::move(line.text);
  return true;
}

void SessionInput::push(const std::string& text) {
  std::lock_guard lock(queue_->mutex);
  queue_->lines.push_back({text, false});
  queue_->ready.notify_one();
}

}  // namespace radiant::cli
