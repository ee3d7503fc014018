#include "render_line.h"

#include "animation_flags.h"
#include "option_parsing.h"

namespace radiant::cli {

namespace fs = std::filesystem;

bool read_command_line(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  int c = buffer ? buffer->sbumpc() : std::char_traits<char>::eof();
  if (c == std::char_traits<char>::eof()) return false;
  for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer->sbumpc()) {
    if (line.size() == max_command_line)
      throw std::invalid_argument("line is longer than " + std::to_string(max_command_line) + " characters");
    line += char(c);
  }
  return true;
}

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false, any = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted, any = true;
    } else if (!quoted && (c == ' ' || c == '\t' || c == '\r')) {
      if (any) words.push_back(word), word.clear(), any = false;
    } else {
      word += c, any = true;
    }
  }
  if (quoted) throw std::invalid_argument("unterminated quote");
  if (any) words.push_back(word);
  return words;
}

void bind_render_line_flags(CLI::App& app, RenderFlags& flags, RenderJob& job) {
  flags.bind(app, true);
  app.add_option("--stats", job.stats_path, "Write render statistics as JSON");
  app.add_option("--aov", flags.aovs, "Extra EXR channels: albedo,normal,depth,variance,spp");
  app.add_option("--crop", flags.crop, "Render only pixels X0,Y0,X1,Y1 (half-open)");
  app.add_option("--noise-threshold", flags.options.noise_threshold, "Adaptive sampling: stop pixels under this relative error")
      ->check(positive_number());
  app.add_option("--min-spp", flags.options.min_spp, "Adaptive sampling: samples every pixel takes first")
      ->check(CLI::Range(1, 1 << 24));
}

RenderJob parse_render_line(std::vector<std::string> words, const fs::path& base, bool with_animation) {
  CLI::App app{"render"};
  RenderFlags flags;
  AnimationFlags animation;
  RenderJob job;
  if (with_animation) animation.bind(app);
  app.add_option("-o,--output", job.output)->required();
  bind_render_line_flags(app, flags, job);
  parse_arguments(app, std::move(words));
  // A view of a scene already loaded cannot change what was loaded.
  for (const char* flag : {"--scene", "--variant"})
    if (app.count(flag))
      throw std::invalid_argument(std::string(flag) +
                                  " chooses what is loaded, not a view of it: give it where the scene is loaded "
                                  "(in a batch script, on the 'scene' line: scene PATH " + flag + " ...)");
  flags.finish();
  job.options = flags.options;
  if (with_animation) {
    LoadOptions moment;
    animation.finish(moment);
    if (animation.frames) throw std::invalid_argument("--frames renders many images: give one render line per frame (--frame N)");
    job.animation_time = moment.animation_time;
    job.animation = moment.animation;
    if (*animation.frame_option) {
      job.options.seed = animation.seed_of_frame(job.options.seed, animation.frame);
      job.frame = FrameNote{animation.frame, 1};
    }
  }
  job.max_memory_bytes = flags.max_memory_bytes;
  job.write_metadata = !flags.no_metadata;
  if (fs::path(job.output).is_relative()) job.output = (base / job.output).string();
  if (!job.stats_path.empty() && fs::path(job.stats_path).is_relative()) job.stats_path = (base / job.stats_path).string();
  if (!job.options.aovs.empty() && !is_exr_format(job.output)) throw std::invalid_argument("--aov needs an EXR output");
  return job;
}

}  // namespace radiant::cli
