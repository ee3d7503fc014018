"""Cycles set up to do radiant's work and nothing else, shared by the Blender bench scripts
(bench/blender_render.py explains each setting)."""


def configure_cycles(scene, size, spp, max_depth, seed):
    """Path tracing on the CPU at SIZE x SIZE, SPP samples, MAX_DEPTH surface interactions
    (radiant's --max-depth; Cycles counts bounces, one fewer), the Standard view."""
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = seed
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.max_bounces = max_depth - 1
    cycles.diffuse_bounces = max_depth - 1
    cycles.glossy_bounces = max_depth - 1
    cycles.transmission_bounces = max_depth - 1
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    scene.render.resolution_x = size
    scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
