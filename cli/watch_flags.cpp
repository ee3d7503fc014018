#include "watch_flags.h"

#include <iostream>

#include "output/output_paths.h"
#include "render/render.h"

namespace radiant::cli {

void WatchFlags::bind(CLI::App& app, bool with_serve) {
  app.add_option("--display-server", display_server,
                 "Stream the image to the tev viewer at HOST:PORT as it converges (tev listens on 127.0.0.1:14158)");
  if (with_serve)
    app.add_option("--serve", serve,
                   "Show the image as it converges on a web page at http://127.0.0.1:PORT (or HOST:PORT to listen "
                   "elsewhere)");
}

Watchers make_watchers(const WatchFlags& flags, std::function<void(const std::string&)> on_command) {
  Watchers w;
  try {
    if (!flags.display_server.empty()) w.display = std::make_shared<DisplayServer>(flags.display_server);
    if (!flags.serve.empty()) w.page = make_live_page(flags.serve, std::move(on_command));
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());  // a usage error, reported as the other flags' are
  }
  if (w.page)
    std::cerr << "radiant: watch the render at " << w.page->url() << "\n";
  return w;
}

void Watchers::show(const std::string& output, const Film& film, uint32_t samples, uint32_t target, double elapsed,
                    const DisplaySettings& look, bool quiet) const {
  if (!any()) return;
  std::string name = is_standard_output(output) ? "radiant" : output;
  OutputImage image = film_to_image(film, {});
  image.display = look;
  if (page) page->show(name, image, samples, target, elapsed);
  if (!display) return;
  display->show(name, image);
  if (std::string warning = display->take_warning(); !warning.empty() && !quiet)
    std::cerr << "radiant: warning: " << warning << "\n";
}

void Watchers::finished() const {
  if (page) page->finished();
}

}  // namespace radiant::cli
