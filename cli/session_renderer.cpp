#include "session_renderer.h"

#include <tbb/task_arena.h>

#include <chrono>
#include <new>

#include "denoise/denoise.h"
#include "denoise/denoise_channels.h"
#include "output/output_set.h"
#include "render_report.h"
#include "watch_flags.h"

namespace radiant::cli {

SessionRenderer::SessionRenderer(Reporter report, ProgressReporter progress)
    : report_(std::move(report)), progress_(std::move(progress)), thread_([this] { run(); }) {}

SessionRenderer::~SessionRenderer() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    pending_.reset();
    stop_ = 1;
  }
  changed_.notify_all();
  thread_.join();
}

void SessionRenderer::start(SessionRequest request) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(request);
    stop_ = 1;  // the render under way, if any, is stale
  }
  changed_.notify_all();
}

void SessionRenderer::cancel() {
  std::lock_guard lock(mutex_);
  pending_.reset();
  stop_ = 1;
}

void SessionRenderer::wait_idle() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !busy_ && !pending_; });
}

std::optional<FinishedRender> SessionRenderer::last_finished() const {
  std::lock_guard lock(mutex_);
  return last_;
}

void SessionRenderer::run() {
  for (;;) {
    {
      SessionRequest request;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return closing_ || pending_; });
        if (closing_) return;
        request = std::move(*pending_);
        pending_.reset();
        busy_ = true;
        stop_ = 0;  // under the lock: a start() after this point stops this render
      }
      render(request);
      progress_(nullptr);
    }  // the request's hold on the scene ends before the session may replace the scene
    {
      std::lock_guard lock(mutex_);
      busy_ = false;
    }
    changed_.notify_all();
  }
}

void SessionRenderer::render(const SessionRequest& request) {
  using Clock = std::chrono::steady_clock;
  const RenderJob& job = request.job;
  try {
    PreparedScene& prepared = *request.scene;
    RenderOptions options = job.options;
    options.stop_request = &stop_;
    options.stop_completes_first_pass = false;  // a stopped render is replaced, never written
    prepare_view(prepared, options);
    PhaseTimes times;
    times.build = prepared.build_seconds;
    ResolvedSettings settings = resolve_settings(prepared, options);
    uint32_t total = uint32_t(settings.spp);
    auto image_of = [&](const Film& film, const RenderResult& so_far) {
      OutputImage image = film_to_image(film, job.options.aovs);
      // Each pass denoised as it comes: a viewer sees a clean image from the first pass on.
      if (job.options.denoise)
        tbb::task_arena(worker_threads(options.threads)).execute([&] {
          set_image_color(image, denoise_film(film, options.memory, request.scene_path));
        });
      set_output_encoding(image, job.options, settings);
      if (job.write_metadata) {
        RenderRecord record = render_record(request.scene_path, job.command_line, job.options.seed, so_far);
        record.denoised = job.options.denoise;
        image.metadata = render_metadata(record);
      }
      return image;
    };
    auto start = Clock::now();
    int pass = 0;
    // Each pass short of the last replaces the image, so a viewer that reloads shows it sharpen;
    // the finished render is written below, with its statistics.
    options.on_pass = [&](const Film& film, uint32_t samples) {
      if (stop_) return;
      double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      job.watchers.show(job.output, film, samples, total, seconds, {job.options.exposure, settings.view},
                        job.options.quiet);
      if (!job.options.quiet) {
        PassProgress progress{job.output, ++pass, samples, total, seconds};
        progress_(&progress);
      }
      if (samples >= total) return;
      RenderResult so_far;  // rays are counted when the render ends: a pass records none
      so_far.settings = settings;
      so_far.settings.spp = int(samples);
      so_far.stats.render_seconds = std::chrono::duration<double>(Clock::now() - start).count();
      OutputImage image = image_of(film, so_far);
      std::erase_if(image.metadata, [](const auto& attribute) { return attribute.first.rfind("radiant:rays", 0) == 0; });
      if (job.write_metadata)
        image.metadata.emplace_back("radiant:partial", "progressive pass: " + std::to_string(samples) + " of " +
                                                           std::to_string(total) + " samples per pixel");
      OutputSet outputs;
      write_image(outputs.create(job.output), image);
      outputs.commit();
    };
    RenderResult result = render_prepared(prepared, options);
    if (result.stats.interrupted) return;  // a newer request replaced it
    times.render = result.stats.render_seconds;
    FinishedRender finished;
    finished.image = image_of(result.film, result);
    if (std::string partial = partial_reason(result); !partial.empty() && job.write_metadata)
      finished.image.metadata.emplace_back("radiant:partial", partial);
    auto write_start = Clock::now();
    OutputSet outputs;
    write_image(outputs.create(job.output), finished.image);
    times.write = std::chrono::duration<double>(Clock::now() - write_start).count();
    if (!job.stats_path.empty())
      outputs.create(job.stats_path).write(render_stats_json(request.scene_path, job.output, result, times));
    outputs.commit();
    finished.summary = render_summary(job.output, result, times);
    {
      std::lock_guard lock(mutex_);
      last_ = finished;
    }
    job.watchers.finished();
    report_(request.line, "", &finished);
  } catch (const std::bad_alloc&) {
    report_(request.line, out_of_memory_message(request.scene_path, "rendering", *request.job.options.memory), nullptr);
  } catch (const std::exception& e) {
    report_(request.line, e.what(), nullptr);
  }
}

}  // namespace radiant::cli
