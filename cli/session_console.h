// What `radiant session` prints, from the command loop and the render thread alike: the prompt,
// the lines that must not land after it (a finished render, an error) and each render's progress.
// On a terminal (ProgressStyle::bar) the progress is one status line kept just above the prompt
// and redrawn in place, so what the user is typing stays where it is; with no prompt on screen it
// is a line redrawn with \r, as render's bar. ProgressStyle::lines prints a line per pass.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>

#include "render/render_options.h"

namespace radiant::cli {

class SessionConsole {
 public:
  // `progress`: the session's --progress; bar and lines only when stderr shows them.
  explicit SessionConsole(ProgressStyle progress) : progress_(progress) {}

  // The prompt on stderr (standard input is a terminal), with the status line above it while a
  // render is under way.
  void show_prompt();
  // A line was read: the prompt is no longer on screen.
  void prompt_answered();
  // `text` on stdout, or on stderr, above the prompt and the status line if they are shown.
  void print_out(const std::string& text);
  void print_error(const std::string& text);
  // A render's pass: every pixel of `output` holds `samples` of `total` samples, after `seconds`.
  void show_pass(const std::string& output, int pass, uint32_t samples, uint32_t total, double seconds);
  // A render was asked for: the prompt shown next keeps a status line for it.
  void render_started(const std::string& output);
  // The render under way ended (finished, failed or replaced): no status until the next pass.
  void render_ended();

 private:
  template <class Print>
  void above_prompt(Print print);

  ProgressStyle progress_;
  std::mutex mutex_;
  bool prompt_shown_ = false;  // "radiant> " is the last line on screen, the user may be typing
  bool status_slot_ = false;   // the line just above the prompt is the status line
  bool bar_shown_ = false;     // no prompt: the current line holds the status, the cursor at its end
  std::string status_;         // the render under way's latest pass; empty: none
};

}  // namespace radiant::cli
