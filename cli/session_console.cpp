#include "session_console.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace radiant::cli {

namespace {

const char* prompt = "radiant> ";
// VT100 sequences every terminal emulator knows.
const char* erase_line = "\r\033[K";
const char* save_cursor = "\0337";
const char* restore_cursor = "\0338";
const char* cursor_up = "\033[A";

std::string format_seconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

}  // namespace

void SessionConsole::show_prompt() {
  std::lock_guard lock(mutex_);
  std::string text;
  if (bar_shown_) text += erase_line;
  bar_shown_ = false;
  // The status line is drawn now, before anything is typed, so that later passes redraw it
  // without touching the prompt's line.
  status_slot_ = progress_ == ProgressStyle::bar && !status_.empty();
  if (status_slot_) text += status_ + "\n";
  std::cerr << text + prompt << std::flush;
  prompt_shown_ = true;
}

void SessionConsole::prompt_answered() {
  std::lock_guard lock(mutex_);
  prompt_shown_ = false;
  status_slot_ = false;  // the user's Enter moved the cursor below both
}

// Erases the prompt (and the status line above it), lets `print` write whole lines, and shows
// both again below.
template <class Print>
void SessionConsole::above_prompt(Print print) {
  std::string erase;
  if (prompt_shown_) erase = erase_line;
  if (prompt_shown_ && status_slot_) erase += std::string(cursor_up) + erase_line;
  if (bar_shown_) erase = erase_line;
  if (!erase.empty()) std::cerr << erase << std::flush;
  bar_shown_ = false;
  print();
  if (!prompt_shown_) return;
  status_slot_ = progress_ == ProgressStyle::bar && !status_.empty();
  std::cerr << (status_slot_ ? status_ + "\n" : std::string()) + prompt << std::flush;
}

void SessionConsole::print_out(const std::string& text) {
  std::lock_guard lock(mutex_);
  if (!isatty(STDOUT_FILENO)) {  // not on the terminal: the prompt and the status line stay as they are
    std::cout << text << (text.empty() || text.back() != '\n' ? "\n" : "") << std::flush;
    return;
  }
  if (prompt_shown_ && status_slot_ && text.find('\n') == std::string::npos) {
    // One line takes the status line's place: what the user is typing stays as it is.
    std::cerr << std::string(save_cursor) + cursor_up + erase_line << std::flush;
    std::cout << text << std::flush;
    std::cerr << restore_cursor << std::flush;
    status_slot_ = false;
    return;
  }
  above_prompt([&] { std::cout << text << (text.empty() || text.back() != '\n' ? "\n" : "") << std::flush; });
}

void SessionConsole::print_error(const std::string& text) {
  std::lock_guard lock(mutex_);
  above_prompt([&] { std::cerr << text << "\n" << std::flush; });
}

void SessionConsole::show_pass(const std::string& output, int pass, uint32_t samples, uint32_t total,
                               double seconds) {
  if (progress_ == ProgressStyle::none) return;
  std::string text = "rendering " + output + ": pass " + std::to_string(pass) + ", " + std::to_string(samples) +
                     " of " + std::to_string(total) + " spp, " + format_seconds(seconds);
  std::lock_guard lock(mutex_);
  if (progress_ == ProgressStyle::lines) {
    above_prompt([&] { std::cerr << "radiant session: " << text << "\n" << std::flush; });
    return;
  }
  status_ = text;
  if (prompt_shown_ && status_slot_)  // redrawn in place; the cursor goes back where the user types
    std::cerr << std::string(save_cursor) + cursor_up + erase_line + status_ + restore_cursor << std::flush;
  else if (!prompt_shown_) {
    std::cerr << erase_line + status_ << std::flush;
    bar_shown_ = true;
  } else {  // a prompt shown while no render was under way: the status goes in above it
    std::cerr << erase_line + status_ + "\n" + prompt << std::flush;
    status_slot_ = true;
  }
}

void SessionConsole::render_started(const std::string& output) {
  if (progress_ != ProgressStyle::bar) return;
  std::lock_guard lock(mutex_);
  status_ = "rendering " + output + ": starting";
}

void SessionConsole::render_ended() {
  std::lock_guard lock(mutex_);
  if (status_.empty()) return;
  status_.clear();
  if (prompt_shown_ && status_slot_)  // a blank line until the next render's first pass
    std::cerr << std::string(save_cursor) + cursor_up + erase_line + restore_cursor << std::flush;
  if (bar_shown_) std::cerr << erase_line << std::flush;
  bar_shown_ = false;
}

}  // namespace radiant::cli
