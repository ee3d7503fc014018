# radiant's layers, lowest first. Each entry is one level; the folders of a level are peers and
# may not include one another. A folder includes (and its library links) only folders of lower
# levels: docs/architecture.md explains the order, tests/check_layers.cmake enforces it.
set(RADIANT_LAYER_LEVELS
  "src/math"
  "src/memory src/output"
  "src/scene"
  "src/sampling src/image"
  "src/materials src/film modules"
  "loaders"
  "src/lights src/accel"
  "src/integrators src/denoise"
  "src/render"
  "src/converge"
  "cli")
