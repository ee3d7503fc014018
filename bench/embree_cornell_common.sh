# Sourced by the embree_cornell*.sh benchmarks: the tutorial's Cornell box as radiant loads it,
# and one command per renderer. Needs $work (a scratch folder) and $threads.
#
# Same geometry and albedos (the tutorial's OBJ/MTL, included unchanged by a .scene), same
# camera, same point light, same path length for both.
command -v pathtracer >/dev/null || { echo "install embree-tools for Embree's pathtracer" >&2; exit 1; }
embree_models=/usr/share/doc/embree3/models
cp "$embree_models/cornell_box.obj" "$embree_models/cornell_box.mtl" "$work/"
# The tutorial's light: -pointlight 213 300 227 100000 100000 100000, radiance I/d^2 in its units.
# A .scene light color C (0-255 scale) is intensity pi*C/255 (docs/scene-format.md), so
# C = 100000 * 255 / pi; attenuation 0 0 1 is the inverse square law.
cat > "$work/cornell.scene" <<SCENE
scene Embree tutorial Cornell box
@camera
position 278 273 -800
look-at 278 273 0
up 0 1 0
fov 37
@light point
color 8116902.1 8116902.1 8116902.1
position 213 300 227
attenuation 0 0 1
@mesh
file cornell_box.obj
SCENE
# The same box as glTF (bench/cornell_obj_to_gltf.py): the general metallic-roughness model
# (metallic 0, roughness 1), the same made exactly Lambertian (specularFactor 0), the general
# model textured (base colour, roughness and normal map), and with a glass tall block (the last
# two are not the tutorial's image any more).
python3 bench/cornell_obj_to_gltf.py "$work/cornell_box.obj" "$work/cornell_box.mtl" "$work/cornell.gltf"
python3 bench/cornell_obj_to_gltf.py "$work/cornell_box.obj" "$work/cornell_box.mtl" "$work/cornell-lambertian.gltf" --lambertian
python3 bench/cornell_obj_to_gltf.py "$work/cornell_box.obj" "$work/cornell_box.mtl" "$work/cornell-textured.gltf" --textured
python3 bench/cornell_obj_to_gltf.py "$work/cornell_box.obj" "$work/cornell_box.mtl" "$work/cornell-glass.gltf" --glass
[[ -f $work/${radiant_scene:-cornell.scene} ]] ||
  { echo "--scene: one of cornell.scene, cornell.gltf, cornell-lambertian.gltf, cornell-textured.gltf," \
         "cornell-glass.gltf, not ${radiant_scene:-}" >&2
    exit 2; }

# embree_render SIZE SPP OUT.ppm [environment for the process...]
embree_render() { embree_render_configured "" "$@"; }
# The same, on the Embree structure radiant traces. radiant sets RTC_SCENE_FLAG_ROBUST, which
# makes Embree build a BVH8 of Triangle4v and intersect it with the watertight Pluecker test
# and robust traversal; the tutorial sets no flag and gets Triangle4 with the faster Moeller-
# Trumbore test. tri_accel=bvh8.triangle4v gives the tutorial radiant's kernel: with
# verbose=2 both report avx512::BVH8Triangle4vIntersector1Pluecker on this machine.
embree_render_robust() { embree_render_configured "tri_accel=bvh8.triangle4v" "$@"; }
# embree_render_configured EMBREE_CONFIG SIZE SPP OUT.ppm [environment for the process...]
embree_render_configured() {
  local config=$1
  shift
  env "${@:4}" pathtracer -c "$embree_models/cornell_box.ecs" ${config:+--rtcore "$config"} --threads "$threads" \
    --size "$1" "$1" --spp "$2" --max-path-length 8 -o "$3" >/dev/null 2>&1
}
# radiant_render SIZE SPP OUT [environment for the process...]; $radiant_seed picks the seed
# (default 0; references use others, bench/equal_error.sh), $radiant_flags adds flags
# (e.g. "--batching all") and $radiant_scene picks the file (default cornell.scene).
radiant_render() {
  env "${@:4}" build/radiant render "$work/${radiant_scene:-cornell.scene}" -o "$3" --width "$1" --height "$1" --spp "$2" --max-depth 8 \
    --mode path --threads "$threads" --seed "${radiant_seed:-0}" --quiet ${radiant_flags:-}
}
