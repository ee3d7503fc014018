#include "fuzz_support.h"

#include <fstream>
#include <stdexcept>

#include "fuzz_folder.h"
#include "load_scene.h"
#include "render/render.h"

namespace radiant::fuzz {

InputFiles::~InputFiles() {
  std::error_code ignored;
  for (const std::filesystem::path& path : written_) std::filesystem::remove_all(path, ignored);
}

std::filesystem::path InputFiles::write(const std::string& name, std::string_view bytes) {
  std::filesystem::path path = folder_ / name;
  written_.push_back(path);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) throw std::logic_error("cannot write the fuzz input " + path.string());
  return path;
}

std::filesystem::path InputFiles::output_folder(const std::string& name) {
  std::filesystem::path path = folder_ / name;
  written_.push_back(path);
  std::filesystem::remove_all(path);
  std::filesystem::create_directory(path);
  return path;
}

FuzzOutcome outcome_of(const std::function<void()>& attempt) {
  try {
    attempt();
  } catch (const LoadError& error) {
    return {Refusal::load, error.what()};
  } catch (const std::runtime_error& error) {  // images, environment maps, CLI11, filesystem
    return {Refusal::other, error.what()};
  } catch (const std::invalid_argument& error) {  // a render setting that makes no sense
    return {Refusal::other, error.what()};
  }
  return {};
}

void render_tiny(const SceneDesc& scene, const std::string& environment_map) {
  PreparedScene prepared = prepare_scene(scene);
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    MemoryBudget budget(fuzz_memory_limit);  // the environment map's decoding and the film
    RenderOptions options;
    options.memory = &budget;
    options.width = options.height = tiny_image_size;
    options.spp = 1;
    options.threads = 1;  // the fuzzers run side by side, one core each
    options.mode = mode;
    options.quiet = true;
    options.env_map = environment_map;
    options.aovs = {"albedo", "normal", "depth", "variance", "spp"};
    RenderResult result = render_prepared(prepared, options);
    film_to_image(result.film, options.aovs);
  }
}

}  // namespace radiant::fuzz
