#include "obj/obj_materials.h"

#include "file_access.h"
#include "image/image_io.h"

namespace radiant {

int load_obj_texture(ObjTextureLoader& textures, const std::string& name, const tinyobj::texture_option_t& option,
                     const std::string& where) {
  std::filesystem::path path =
      resolve_inside(textures.base_dir, name, textures.options.allow_external_files, where);
  std::string key = path.string() + (option.clamp ? "#clamp" : "");
  auto found = textures.textures_by_path.find(key);
  if (found != textures.textures_by_path.end()) return found->second;
  check_input_file(path, where + " '" + name + "'", textures.options);
  std::string error;
  auto input = open_image_file(path.string(), error);
  if (!input) throw LoadError(where + ": cannot read image '" + name + "'");
  const ImageHeader& spec = input->header();
  int channels = std::min(spec.channels, 4);
  std::string image_label = where + ": image '" + name + "' (" + std::to_string(spec.width) + "x" +
                            std::to_string(spec.height) + ")";
  uint64_t texels = uint64_t(std::max(spec.width, 0)) * uint64_t(std::max(spec.height, 0));
  if (texels == 0 || channels <= 0) throw LoadError(image_label + ": the image is empty");
  // OpenImageIO may hold the whole file's pixels (up to four bytes a channel) while it converts.
  charge_load(textures.options, saturating_multiply(texels, uint64_t(std::max(spec.channels, 0)) * 4 + channels),
              image_label);
  ImageDesc image;
  image.name = path.string();
  image.width = spec.width, image.height = spec.height, image.channels = channels;
  image.texels8.resize(texels * channels);
  if (!input->read(channels, PixelType::uint8, image.texels8.data()))
    throw LoadError(where + ": cannot decode image '" + name + "': " + input->error());
  TextureDesc texture;
  texture.image = int(textures.scene.images.size());
  if (option.clamp) texture.wrap_s = texture.wrap_t = TextureWrap::clamp_to_edge;
  textures.scene.images.push_back(std::move(image));
  int index = int(textures.scene.textures.size());
  textures.scene.textures.push_back(texture);
  textures.textures_by_path[key] = index;
  return index;
}

static color3 rgb(const tinyobj::real_t* v) { return {float(v[0]), float(v[1]), float(v[2])}; }

// The MTL illum models that trace refraction (glass) or mirror reflection.
static bool is_glass(int illum) { return illum == 4 || illum == 6 || illum == 7 || illum == 9; }
static bool is_mirror(int illum) { return illum == 3 || illum == 5 || (is_glass(illum) && illum != 9); }

MaterialDesc convert_mtl_material(ObjTextureLoader& textures, const tinyobj::material_t& source) {
  MaterialDesc material;
  material.name = source.name;
  material.model = MaterialModel::phong;
  material.ka = rgb(source.ambient);
  material.kd = rgb(source.diffuse);
  material.ks = rgb(source.specular);
  material.shininess = source.shininess > 0 ? float(source.shininess) : 1;
  material.emission = rgb(source.emission);
  material.ior = source.ior > 0 ? float(source.ior) : 1.5f;
  if (is_mirror(source.illum)) material.kr = material.ks;
  if (is_glass(source.illum)) {
    color3 filter = rgb(source.transmittance);
    float clear = 1 - float(source.dissolve);
    material.kt = is_black(filter) ? color3{clear, clear, clear} : filter;
  } else {
    material.alpha = float(source.dissolve);
    if (material.alpha < 1) material.alpha_mode = AlphaMode::blend;
  }
  std::string where = textures.file + ": material '" + source.name + "'";
  auto texture = [&](const std::string& name, const tinyobj::texture_option_t& option, const char* key) {
    TextureRef ref;
    if (!name.empty()) ref.texture = load_obj_texture(textures, name, option, where + " " + key);
    return ref;
  };
  material.base_color_texture = texture(source.diffuse_texname, source.diffuse_texopt, "map_Kd");
  material.specular_texture = texture(source.specular_texname, source.specular_texopt, "map_Ks");
  material.emission_texture = texture(source.emissive_texname, source.emissive_texopt, "map_Ke");
  material.alpha_texture = texture(source.alpha_texname, source.alpha_texopt, "map_d");
  if (material.alpha_texture.valid()) material.alpha_mode = AlphaMode::mask;
  material.normal_texture = !source.normal_texname.empty()
                                ? texture(source.normal_texname, source.normal_texopt, "norm")
                                : texture(source.bump_texname, source.bump_texopt, "map_bump");
  return material;
}

}  // namespace radiant
