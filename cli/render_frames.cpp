#include "render_frames.h"

#include <iostream>
#include <new>

#include "commands.h"

namespace radiant::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Makes, prepares (from the frame before) and renders frame `number` of `file` (read `reads`
// times by this command).
void render_frame(SceneFile& file, FrameScene& frame, int reads, const FramesRequest& request,
                  const AnimationFlags& animation, long long number, double read_seconds) {
  auto start = Clock::now();
  LoadOptions load = request.load;
  load.animation_time = animation.frame_time(number);
  RenderJob job = request.job;
  job.output = frame_path(request.output_pattern, number);
  if (!request.stats_pattern.empty()) job.stats_path = frame_path(request.stats_pattern, number);
  job.options.seed = animation.seed_of_frame(request.job.options.seed, number);
  check_render_job_outputs(job);
  FramePreparation how = frame.prepare_next(file, load, job.options);
  job.frame = FrameNote{number, reads, how == FramePreparation::updated};
  job.notes = number == animation.frames->first;  // every frame would say the same
  if (!job.options.quiet_warnings && job.notes)
    for (const std::string& warning : frame.prepared->scene->warnings) std::cerr << "radiant: warning: " << warning << "\n";
  PhaseTimes times;
  times.load = read_seconds + seconds_since(start) - frame.prepared->build_seconds;
  run_render_job(request.scene_path, *frame.prepared, job, times);
}

}  // namespace

FramePreparation FrameScene::prepare_next(SceneFile& file, const LoadOptions& load, const RenderOptions& options) {
  MemoryBudget* budget = load.budget;
  uint64_t used_before = budget->used();
  SceneDesc scene = scene_from_file(file, load);
  MemoryCharge memory = MemoryCharge::adopt(budget, budget->used() - used_before);
  return prepare_frame(prepared, std::move(scene), std::move(memory), options);
}

int render_frames(const FramesRequest& request, const AnimationFlags& animation) {
  const RenderOptions& options = request.job.options;
  SceneFile file;
  FrameScene frame;
  int reads = 0;
  try {
    file = read_scene_file(request.scene_path, request.load);
    ++reads;
  } catch (const std::bad_alloc&) {
    std::cerr << "radiant: " << out_of_memory_message(request.scene_path, "loading", *options.memory) << "\n";
    return exit_failure;
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  double read_seconds = seconds_since(request.start);
  const FrameRange& frames = *animation.frames;
  if (!options.quiet)
    std::cerr << "radiant: read " << request.scene_path << " once for frames " << frames.first << "-" << frames.last
              << " at " << animation.fps << " fps\n";
  for (long long number = frames.first; number <= frames.last; ++number) {
    try {
      render_frame(file, frame, reads, request, animation, number, number == frames.first ? read_seconds : 0);
    } catch (const std::invalid_argument& e) {  // a setting every frame shares: the first refuses it
      std::cerr << "radiant render: frame " << number << ": " << e.what() << "\n";
      return exit_usage;
    } catch (const std::bad_alloc&) {
      std::cerr << "radiant: frame " << number << ": "
                << out_of_memory_message(request.scene_path, "rendering", *options.memory) << "\n";
      return exit_failure;
    } catch (const std::exception& e) {
      std::cerr << "radiant: frame " << number << ": " << e.what() << "\n";
      return exit_failure;
    }
  }
  return exit_ok;
}

}  // namespace radiant::cli
