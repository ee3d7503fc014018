// The image target: the bytes as an image file, read as `radiant compare` reads its inputs and
// as the renderer reads an environment map (then rendered under it). The file is named for the
// format its magic says (PNG, OpenEXR, Radiance HDR, JPEG), as a user would name it.
#include "fuzz_folder.h"
#include "fuzz_support.h"
#include "image/compare.h"
#include "load_scene.h"

namespace radiant::fuzz {

namespace {

namespace fs = std::filesystem;

std::string image_file_name(const std::string& bytes) {
  auto starts_with = [&](std::string_view magic) { return bytes.compare(0, magic.size(), magic) == 0; };
  if (starts_with("\x76\x2f\x31\x01")) return "fuzz.exr";
  if (starts_with("#?")) return "fuzz.hdr";
  if (starts_with("\xff\xd8\xff")) return "fuzz.jpg";
  return "fuzz.png";
}

}  // namespace

FuzzOutcome run_image_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  std::string image = files.write(image_file_name(bytes), bytes).string();
  // One chain, so a file that does not open costs one open: OpenEXR allocates what a header
  // declares (hundreds of MB from a few bytes), which ASan makes slow.
  return outcome_of([&] {
    MemoryBudget budget(fuzz_memory_limit);
    CompareImage read = read_compare_image(image, &budget);
    read_variance_image(image, read, 1, &budget);
    LoadOptions options;
    options.max_memory_bytes = fuzz_memory_limit;
    render_tiny(load_scene((folder / "first-render.scene").string(), options), image);
  });
}

}  // namespace radiant::fuzz
