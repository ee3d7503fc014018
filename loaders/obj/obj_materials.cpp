#include "obj/obj_materials.h"

#include "file_access.h"
#include "memory/input_file.h"
#include "message_text.h"
#include "obj/obj_paths.h"
#include "texture_file.h"

namespace radiant {

int load_obj_texture(ObjTextureLoader& textures, const std::string& written_name, const tinyobj::texture_option_t& option,
                     const std::string& where) {
  std::string name = portable_path(written_name);
  std::filesystem::path path =
      resolve_inside(textures.base_dir, name, textures.options.allow_external_files, where);
  std::string key = path.string() + (option.clamp ? "#clamp" : "");
  auto found = textures.textures_by_path.find(key);
  if (found != textures.textures_by_path.end()) return found->second;
  std::string label = where + " '" + escaped(name) + "'";
  uint64_t size = 0;
  if (input_file_problem(path, size) == no_such_file) {
    textures.scene.warnings.push_back(label + ": " + no_such_file + "; the material is rendered without it");
    textures.textures_by_path[key] = -1;
    return -1;
  }
  ImageDesc image = read_texture_file(path, where, name, textures.options);
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
  std::string where = textures.file + ": material '" + escaped(source.name) + "'";
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
  material.normal_texture = texture(source.normal_texname, source.normal_texopt, "norm");
  material.bump_texture = texture(source.bump_texname, source.bump_texopt, "bump");
  material.bump_scale = float(source.bump_texopt.bump_multiplier);
  return material;
}

}  // namespace radiant
