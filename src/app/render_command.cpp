#include "app/commands.hpp"
#include "app/measure.hpp"
#include "app/method_settings.hpp"
#include "app/output_check.hpp"
#include "app/scene_source.hpp"
#include "app/tone_options.hpp"
#include "core/atomic_file.hpp"
#include "core/image_io.hpp"
#include "gpu/program.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include <nlohmann/json.hpp>
#include <oneapi/tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

namespace airlight::app {

namespace {

struct RenderOptions {
  SceneSource scene;
  std::string method = "reference", size = "256x192", pass = "composite", out, report;
  std::vector<std::string> assignments;
  ToneOptions tone;
  int threads = 0;  // 0: all cores
};

Pass parse_pass(const std::string& name) {
  if (name == "airlight") return Pass::airlight;
  if (name == "surface") return Pass::surface;
  return Pass::composite;
}

// Min, mean and max per channel; a non-finite pixel is a method's bug and fails the render.
nlohmann::json image_stats(const Image& image, const std::string& method) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY), sum(0.0);
  long bad = 0;
  for (const auto& p : image.pixels) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(p[c])) ++bad;
      lo[c] = std::min<double>(lo[c], p[c]);
      hi[c] = std::max<double>(hi[c], p[c]);
      sum[c] += p[c];
    }
  }
  if (bad) throw Failure("method '" + method + "' produced " + std::to_string(bad) + " non-finite values");
  const glm::dvec3 mean = sum / static_cast<double>(image.pixels.size());
  auto rgb = [](const glm::dvec3& v) { return nlohmann::json::array({v.r, v.g, v.b}); };
  return {{"min", rgb(lo)}, {"mean", rgb(mean)}, {"max", rgb(hi)}};
}

void write_report(const RenderOptions& o, const Scene& scene, const Settings& settings, const FrameImages& frame,
                  const nlohmann::json& output, const ToneMap& tone, double prepare_s, double render_s) {
  nlohmann::json passes = nlohmann::json::array(), stats = nlohmann::json::object();
  for (const auto& t : frame.times) passes.push_back({{"pass", t.pass}, {"seconds", t.seconds}});
  for (const auto& [name, value] : frame.stats) stats[name] = value;
  const nlohmann::json report{
      {"scene", {{"name", scene.name}, {"file", scene.source.string()}}},
      {"method", o.method},
      {"settings", settings.to_json()},
      {"size", {frame.airlight.width, frame.airlight.height}},
      {"pass", o.pass},
      {"timings", {{"prepare_s", prepare_s}, {"render_s", render_s}, {"readback_s", frame.readback_s}, {"passes", passes}}},
      {"output", output},
      {"tonemap", {{"curve", tone_curve_name(tone.curve)}, {"exposure", tone.exposure}, {"auto", !o.tone.exposure}}},
      {"stats", stats},
      {"programs_compiled", gpu::cached_program_count()},
      {"peak_rss_mib", peak_rss_mib()}};
  write_text_file(o.report, report.dump(2) + "\n");
}

void render(const RenderOptions& o) {
  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
  const Size size = parse_size(o.size, "--size");
  const MethodInfo& info = find_method(o.method, "--method");
  const Settings settings = method_settings(info, o.assignments);
  check_output_file("--out", o.out, {".png", ".pfm", ".exr"});
  if (!o.report.empty()) check_output_file("--report", o.report, {".json"});
  check_memory("--size", size, {&info});
  const Scene scene = o.scene.load();
  const MethodRun run{&info, &settings};
  check_frame_memory(scene, "--size", size, {run});
  const Pass pass = parse_pass(o.pass);
  double prepare_s = 0.0, render_s = 0.0;
  FrameImages frame;
  with_memory_hint(scene, size, run, [&] {
    auto method = info.create(settings);
    auto start = std::chrono::steady_clock::now();
    method->prepare(scene);
    prepare_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    frame = airlight::render(*method, scene, size.width, size.height, pass != Pass::airlight);
    render_s = seconds_since(start);
  });
  const Image image = select_pass(frame, pass);
  const nlohmann::json output = image_stats(image, o.method);
  const ToneMap tone = o.tone.resolve(image, "render");
  OutputBatch outputs;
  write_image(image, o.out, tone);
  if (!o.report.empty()) write_report(o, scene, settings, frame, output, tone, prepare_s, render_s);
  outputs.commit();
}

}  // namespace

Run add_render_command(CLI::App& cli) {
  auto o = std::make_shared<RenderOptions>();
  auto* command = cli.add_subcommand("render", "render a scene by one method");
  o->scene.add_options(*command);
  command->add_option("--method", o->method, "method (airlight list methods)")->capture_default_str();
  command->add_option("--set", o->assignments, "method setting key=value (repeatable)");
  command->add_option("--size", o->size, "image size WxH")->capture_default_str();
  command->add_option("--pass", o->pass, "what to write")
      ->check(CLI::IsMember({"composite", "airlight", "surface"}))
      ->capture_default_str();
  command->add_option("--out", o->out, "output image: .png (tone-mapped), .pfm or .exr (linear)")->required();
  command->add_option("--report", o->report,
                      "JSON report: scene, method, settings, size, timings, output range, PNG tone map");
  o->tone.add_options(*command);
  command->add_option("--threads", o->threads, "CPU threads (0: all cores)")->check(CLI::Range(0, 1024));
  return [o] { render(*o); };
}

}  // namespace airlight::app
