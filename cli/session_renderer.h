// The render thread of `radiant session`: renders one request at a time, rewrites the image
// after every progressive pass, and drops a render as soon as a newer request arrives.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "image/image_writer.h"
#include "render/render.h"
#include "render_job.h"

namespace radiant::cli {

struct SessionRequest {
  int line = 0;                            // the command that asked for it, for messages
  std::shared_ptr<PreparedScene> scene;    // used only by the render thread while it renders
  std::string scene_path;
  RenderJob job;
};

// What a finished render left: the image for `save`, and the line the session printed.
struct FinishedRender {
  OutputImage image;
  std::string summary;
};

// A progressive pass of the render under way: every pixel of `output` holds `samples` of `total`.
struct PassProgress {
  std::string output;
  int pass = 0;
  uint32_t samples = 0, total = 0;
  double seconds = 0;
};

class SessionRenderer {
 public:
  // `report(line, message)` is called from the render thread: an error of the request from
  // command `line` (message empty: none) and, when it finishes, `finished` holds its result.
  using Reporter = std::function<void(int line, const std::string& error, const FinishedRender* finished)>;
  // `progress(pass)` is called from the render thread after each pass of a render that is not
  // quiet, and with null once the render has ended, however it ended.
  using ProgressReporter = std::function<void(const PassProgress* pass)>;
  SessionRenderer(Reporter report, ProgressReporter progress);
  ~SessionRenderer();  // cancels what runs and joins the thread
  SessionRenderer(const SessionRenderer&) = delete;
  SessionRenderer& operator=(const SessionRenderer&) = delete;

  // Renders `request` next: a render under way stops at its next pixel, an unstarted request
  // is replaced.
  void start(SessionRequest request);
  // Stops what runs and drops what waits.
  void cancel();
  // Returns once nothing runs and nothing waits.
  void wait_idle();
  // The last render that finished, if any.
  std::optional<FinishedRender> last_finished() const;

 private:
  void run();
  void render(const SessionRequest& request);

  Reporter report_;
  ProgressReporter progress_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<SessionRequest> pending_;
  bool busy_ = false, closing_ = false;
  std::atomic<int> stop_{0};  // RenderOptions::stop_request of the render under way
  std::optional<FinishedRender> last_;
  std::thread thread_;  // last: starts after everything it uses
};

}  // namespace radiant::cli
