// Watching a render as it converges (docs/cli.md, "Watching a render"): --display-server streams
// it to the tev viewer, --serve shows it on a small web page. `render`, `batch` and `session`
// take them; each pass of a watched render is shown in both.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "film/film.h"
#include "image/display_server.h"
#include "live_page.h"

namespace radiant::cli {

struct WatchFlags {
  std::string display_server, serve;
  // `serve`: whether the command offers --serve (a batch has no page of its own).
  void bind(CLI::App& app, bool serve);
};

// Where a render's passes go; empty: nowhere, and the render runs in one pass.
struct Watchers {
  std::shared_ptr<DisplayServer> display;
  std::shared_ptr<LivePage> page;
  bool any() const { return display || page; }
  // The film after a pass, `samples` of `target` per pixel, shown under the output's name (its
  // path, or "radiant" for standard output). The viewer's first failure prints one warning
  // unless quiet.
  // The page shows it as the output's `look` (exposure, view transform) would; tev gets it linear.
  void show(const std::string& output, const Film& film, uint32_t samples, uint32_t target, double elapsed,
            const DisplaySettings& look, bool quiet) const;
  void finished() const;
};

// The watchers the flags ask for; CLI::ValidationError for an address that is not one, and
// std::runtime_error when the page cannot listen. `on_command`: the page takes commands.
Watchers make_watchers(const WatchFlags& flags, std::function<void(const std::string&)> on_command = {});

}  // namespace radiant::cli
