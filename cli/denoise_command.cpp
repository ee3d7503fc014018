// `radiant denoise IN.exr -o OUT`: the denoiser run on an EXR that holds its channels (a render
// or a merge with --aov albedo,normal,depth,halves), written like `render` writes.
#include <tbb/task_arena.h>

#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "denoise/denoise.h"
#include "denoise/denoise_channels.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "option_parsing.h"
#include "output/output_paths.h"
#include "output/output_set.h"
#include "render/render.h"

namespace radiant::cli {

namespace {

const char* denoise_examples =
    "\nExamples:\n"
    "  radiant render scene.gltf -o noisy.exr --spp 16 --aov albedo,normal,depth,halves\n"
    "  radiant denoise noisy.exr -o clean.png\n"
    "  radiant denoise noisy.exr -o clean.exr --aov noisy   # the input colour kept as noisy.R, G, B\n";

struct DenoiseRequest {
  std::string input, output;
  bool keep_noisy = false, quiet = false, metadata = true;
  int threads = 0;
};

// The image `request.input` denoised: in EXR every input channel (R, G, B denoised, and the input
// colour as noisy.R, G, B when asked), in other formats the colour and alpha.
OutputImage denoised_image(const DenoiseRequest& request, const std::string& command_line, MemoryBudget& budget) {
  std::string error;
  std::unique_ptr<ImageSource> source = open_image_file(request.input, error, &budget);
  if (!source) throw std::runtime_error(request.input + ": " + error);
  const ImageHeader& header = source->header();
  size_t count = size_t(header.width) * size_t(header.height), channels = size_t(header.channels);
  bool exr = is_exr_format(request.output);
  MemoryCharge pixels_memory(&budget, saturating_multiply(count, (2 * channels + 3) * sizeof(float)),
                             request.input + ": its " + std::to_string(header.width) + "x" +
                                 std::to_string(header.height) + " pixels and the image written");
  std::vector<float> pixels(count * channels);
  if (!source->read(int(channels), PixelType::float32, pixels.data()))
    throw std::runtime_error(request.input + ": " + source->error());
  MemoryCharge denoise_memory = charge_denoise(&budget, header.width, header.height, request.input);
  DenoiseInput in = denoise_input_from_channels(header.width, header.height, header.channel_names, pixels, request.input);
  bool alpha = std::find(header.channel_names.begin(), header.channel_names.end(), "A") != header.channel_names.end();
  OutputImage image;
  image.width = header.width, image.height = header.height;
  image.x = header.x, image.y = header.y, image.full_width = header.full_width, image.full_height = header.full_height;
  if (exr) {
    image.channels = header.channel_names;
    image.pixels = std::move(pixels);
  } else {
    // Colour and alpha only: the other channels have no place in a display image.
    image.channels = {"R", "G", "B"};
    if (alpha) image.channels.push_back("A");
    image.pixels.resize(count * image.channels.size());
    for (size_t i = 0; i < count; ++i)
      for (size_t k = 0; k < image.channels.size(); ++k) {
        size_t from = std::find(header.channel_names.begin(), header.channel_names.end(), image.channels[k]) -
                      header.channel_names.begin();
        image.pixels[i * image.channels.size() + k] = pixels[i * channels + from];
      }
  }
  if (request.keep_noisy) {
    std::vector<float> with_noisy;
    size_t stride = image.channels.size();
    with_noisy.reserve(count * (stride + 3));
    for (size_t i = 0; i < count; ++i) {
      with_noisy.insert(with_noisy.end(), &image.pixels[i * stride], &image.pixels[(i + 1) * stride]);
      with_noisy.insert(with_noisy.end(), {in.color[i].x, in.color[i].y, in.color[i].z});
    }
    image.channels.insert(image.channels.end(), {"noisy.R", "noisy.G", "noisy.B"});
    image.pixels = std::move(with_noisy);
  }
  tbb::task_arena(worker_threads(request.threads)).execute([&] { set_image_color(image, denoise(in)); });
  if (request.metadata) {
    image.metadata = radiant_attributes(header.metadata);
    if (!find_attribute(image.metadata, "Software")) image.metadata.emplace_back("Software", "radiant " RADIANT_VERSION);
    image.metadata.emplace_back("radiant:denoise_command", command_line);
    if (!find_attribute(image.metadata, "radiant:denoised")) image.metadata.emplace_back("radiant:denoised", "yes");
  }
  return image;
}

}  // namespace

int denoise_main(int argc, char** argv) {
  CLI::App app{"Denoise an EXR that holds colour, albedo, normal, depth and the half images "
               "(render or merge with --aov albedo,normal,depth,halves)."};
  app.footer(denoise_examples);
  DenoiseRequest request;
  std::string max_memory, aovs;
  bool no_metadata = false;
  app.add_option("IN", request.input, "EXR with the denoiser's channels")->required();
  app.add_option("-o,--output", request.output, "Output image (.png is 8-bit sRGB, .exr linear float)")->required();
  app.add_option("--aov", aovs, "noisy: keep the input colour as noisy.R, noisy.G, noisy.B (EXR)");
  app.add_option("--threads", request.threads, "Worker threads (default: all cores)")->check(CLI::Range(0, 1 << 16));
  app.add_option("--max-memory", max_memory, "Memory cap in GiB (default 1/4 of RAM)");
  app.add_flag("--no-metadata", no_metadata, "Record nothing about the image's making in it");
  app.add_flag("--quiet,-q", request.quiet, "Print nothing but errors");
  std::optional<uint64_t> max_memory_bytes;
  try {
    app.parse(argc, argv);
    if (!max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", max_memory);
    if (!aovs.empty() && aovs != "noisy") throw CLI::ValidationError("--aov", "'" + aovs + "': only noisy is known here");
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant denoise: " << e.what() << "\n";
    return exit_usage;
  }
  request.keep_noisy = aovs == "noisy";
  request.metadata = !no_metadata;
  MemoryBudget budget = command_memory_budget(max_memory_bytes);
  try {
    if (request.keep_noisy && !is_exr_format(request.output))
      throw std::invalid_argument("--aov needs an EXR output (got '" + request.output + "')");
    DistinctFiles files;
    files.add_input({"IN", request.input});
    files.add_output({"-o", request.output});
    check_image_output(request.output);
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiant denoise: " << e.what() << "\n";
    return exit_usage;
  }
  try {
    check_output_place(request.output);
    OutputImage image = denoised_image(request, command_line_text(argc, argv), budget);
    OutputSet outputs;
    write_image(outputs.create(request.output), image);
    outputs.commit();
    if (!request.quiet) std::cerr << "radiant: denoised " << request.input << " into " << request.output << "\n";
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli
