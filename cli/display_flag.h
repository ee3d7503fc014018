// --display-server HOST:PORT: `render`, `batch` and `session` stream their images to a running
// tev viewer as they converge (docs/cli.md, "Watching a render").
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "film/film.h"
#include "image/display_server.h"

namespace radiant::cli {

void add_display_server_flag(CLI::App& app, std::string& address);
// The connection for `address`, or null when none was asked for; CLI::ValidationError when the
// address is not HOST:PORT. It connects on first use.
std::shared_ptr<DisplayServer> make_display_server(const std::string& address);
// The image of `output` in the viewer: its file name, or "radiant" for standard output.
std::string display_name(const std::string& output);
// Shows the film's linear colour under `name`; the first failure prints one warning unless quiet.
void show_film(DisplayServer& display, const std::string& name, const Film& film, bool quiet);

}  // namespace radiant::cli
