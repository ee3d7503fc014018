#include "texture_file.h"

#include "file_access.h"
#include "image/image_io.h"
#include "memory/memory_budget.h"
#include "message_text.h"

namespace radiant {

ImageDesc read_texture_file(const std::filesystem::path& path, const std::string& where, const std::string& name,
                            const LoadOptions& options) {
  check_input_file(path, where + " '" + escaped(name) + "'", options);
  std::string error;
  std::unique_ptr<ImageSource> input;
  try {
    input = open_image_file(path.string(), error, options.budget);
  } catch (const MemoryLimitError& e) {
    throw LoadError(where + ": image '" + escaped(name) + "': " + e.what());
  }
  if (!input) throw LoadError(where + ": cannot read image '" + escaped(name) + "'");
  const ImageHeader& spec = input->header();
  int channels = std::min(spec.channels, 4);
  std::string image_label = where + ": image '" + escaped(name) + "' (" + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) + ")";
  uint64_t texels = uint64_t(std::max(spec.width, 0)) * uint64_t(std::max(spec.height, 0));
  if (texels == 0 || channels <= 0) throw LoadError(image_label + ": the image is empty");
  // OpenImageIO's copy while it converts is the source's charge; the texels stay loaded.
  charge_load(options, saturating_multiply(texels, uint64_t(channels)), image_label);
  ImageDesc image;
  image.name = path.string();
  image.width = spec.width, image.height = spec.height, image.channels = channels;
  image.texels8.resize(texels * channels);
  if (!input->read(channels, PixelType::uint8, image.texels8.data()))
    throw LoadError(where + ": cannot decode image '" + escaped(name) + "': " + one_line(input->error()));
  return image;
}

}  // namespace radiant
