#include "display_flag.h"

#include <iostream>

#include "output/output_paths.h"
#include "render/render.h"

namespace radiant::cli {

void add_display_server_flag(CLI::App& app, std::string& address) {
  app.add_option("--display-server", address,
                 "Stream the image to the tev viewer at HOST:PORT as it converges (tev listens on 127.0.0.1:14158)");
}

std::shared_ptr<DisplayServer> make_display_server(const std::string& address) {
  if (address.empty()) return nullptr;
  try {
    return std::make_shared<DisplayServer>(address);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());  // a usage error, reported as the other flags' are
  }
}

std::string display_name(const std::string& output) { return is_standard_output(output) ? "radiant" : output; }

void show_film(DisplayServer& display, const std::string& name, const Film& film, bool quiet) {
  display.show(name, film_to_image(film, {}));
  if (std::string warning = display.take_warning(); !warning.empty() && !quiet)
    std::cerr << "radiant: warning: " << warning << "\n";
}

}  // namespace radiant::cli
