#include "server/renders/render_job.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "api/render_schema.hpp"
#include "engine/render/pass_schedule.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "server/renders/denoise_share.hpp"
#include "server/renders/render_coordinator.hpp"

namespace lp::server {

namespace {

// The images of the passes `passes` holds, each made by `mean(pass)`.
template <class Mean>
PassImages pass_images(const render::PassSet& passes, Mean&& mean) {
  PassImages out;
  for (const auto p : passes.list()) out[size_t(p)] = std::make_shared<const Image>(mean(p));
  return out;
}

}  // namespace

RenderJob::RenderJob(RenderRecord record, api::RenderRequest request, std::shared_ptr<const EnvMap> envmap,
                     RenderImage image, RenderJobContext context)
    : Job(record.id, record.created, record.elapsed_s),
      request_(std::move(request)),
      request_json_(std::move(record.request)),
      envmap_(std::move(envmap)),
      counters_(context.counters),
      scale_out_(std::move(context.scale_out)),
      denoiser_(context.denoiser),
      earlier_stats_(record.stats),
      earlier_render_s_(record.render_s),
      image_(std::move(image.image)),
      passes_(std::move(image.passes)),
      denoised_(image_ ? std::move(image.denoised) : nullptr),
      denoise_s_(denoised_ ? image.denoise_s : std::nullopt),
      spp_done_(image_ ? record.spp_done : 0),
      ranges_done_(image_ ? record.ranges_done : std::vector<render::SampleRange>{}),
      stats_(record.stats),
      render_s_(record.render_s),
      envmap_fingerprint_(record.envmap_fingerprint),
      model_hashes_(record.model_hashes),
      memory_(std::move(context.memory)),
      files_(context.store, record.id, image_ ? record.image_file : "", request_.settings.passes,
             denoised_ ? record.denoise_s : std::nullopt) {
  set_work(request_.settings.spp, spp_done_);  // until run() counts in tiles
}

RenderImage RenderJob::image() const {
  std::lock_guard lock(mutex_);
  return {image_, spp_done_, passes_, denoised_, denoise_s_};
}

int RenderJob::spp_done() const {
  std::lock_guard lock(mutex_);
  return spp_done_;
}

int64_t RenderJob::retained_bytes() const {
  std::lock_guard lock(mutex_);
  int64_t bytes = image_ ? int64_t(image_->data().size_bytes()) : 0;
  if (denoised_) bytes += int64_t(denoised_->data().size_bytes());
  for (const auto& pass : passes_)
    if (pass) bytes += int64_t(pass->data().size_bytes());
  return bytes;
}

void RenderJob::keep_result_memory() {
  memory_.resize(std::min(memory_.bytes(), retained_bytes()));
  memory_.set_use(MemoryUse::Held);
}

RenderRecord RenderJob::record() const {
  return record(status(), error());
}

RenderRecord RenderJob::record(JobStatus status, const std::optional<JobError>& error) const {
  RenderRecord r;
  r.id = id();
  r.created = created();
  r.request = request_json_;
  r.status = status;
  r.error = error;
  r.elapsed_s = elapsed_s();
  r.image_file = files_.image_file();  // not under mutex_: a checkpoint holds the files' lock while it writes
  r.denoise_s = files_.denoise_s();
  std::lock_guard lock(mutex_);
  r.spp_done = spp_done_;
  r.ranges_done = ranges_done_;
  r.envmap_fingerprint = envmap_fingerprint_;
  r.model_hashes = model_hashes_;
  r.stats = stats_;
  r.render_s = render_s_;
  return r;
}

void RenderJob::publish(Image pixels, PassImages passes, int spp_done, render::RenderStats stats,
                        double render_s, std::vector<render::SampleRange> ranges_done) {
  auto image = std::make_shared<const Image>(std::move(pixels));
  std::lock_guard lock(mutex_);
  if (counters_)
    counters_->add(earlier_stats_.samples + stats.samples - stats_.samples,
                   earlier_stats_.rays + stats.rays - stats_.rays, earlier_render_s_ + render_s - render_s_);
  image_ = std::move(image);
  passes_ = std::move(passes);
  denoised_.reset();  // of an earlier image
  denoise_s_.reset();
  spp_done_ = spp_done;
  ranges_done_ = std::move(ranges_done);
  stats_ = {earlier_stats_.samples + stats.samples, earlier_stats_.rays + stats.rays};
  render_s_ = earlier_render_s_ + render_s;
}

void RenderJob::checkpoint() {
  if (!files_.keeps()) return;
  const RenderImage current = image();
  RenderRecord kept = record();
  kept.envmap_fingerprint = envmap_content_hash(*envmap_);
  kept.model_hashes = run_model_hashes_;
  if (!files_.save_image(current, kept)) return;
  std::lock_guard lock(mutex_);
  envmap_fingerprint_ = kept.envmap_fingerprint;
  model_hashes_ = kept.model_hashes;
}

// Drops the passes an earlier run finished; returns the samples per pixel they hold. An adaptive render
// keeps neither its pixels' sample counts nor their noise across runs, so it starts over.
int RenderJob::skip_done_passes(std::vector<render::RenderPass>& passes) const {
  const int done = spp_done();
  if (done == 0) return 0;
  if (request_.settings.sampling == render::SamplingMode::Adaptive) {
    spdlog::info("render {} starts over: an adaptive render does not continue from {} spp", id(), done);
    return 0;
  }
  int sum = 0;
  size_t skipped = 0;
  while (skipped < passes.size() && sum < done) sum += passes[skipped++].spp;
  if (sum != done)
    throw std::runtime_error(fmt::format("{} samples per pixel done is not the end of a pass", done));
  passes.erase(passes.begin(), passes.begin() + std::ptrdiff_t(skipped));
  return done;
}

bool RenderJob::run() {
  const auto& s = request_.settings;
  spdlog::info("render {} started: {}x{}, {} spp, depth {}, envmap '{}', {}, lighting {}", id(), s.width,
               s.height, s.spp, s.max_depth, request_.envmap,
               request_.preset ? "preset " + *request_.preset
                               : std::to_string(request_.scene.objects.size()) + " objects",
               enum_name(request_.lighting.mode));
  auto release = [this](const char* how) {
    envmap_.reset();
    spdlog::info("render {} {} after {:.2f} s ({} spp done)", id(), how, elapsed_s(), spp_done());
  };
  try {
    if (files_.keeps()) run_model_hashes_ = model_content_hashes(request_.scene);
    // An adaptive render's passes depend on the whole image so far: it is never split into ranges.
    const bool uniform = request_.settings.sampling == render::SamplingMode::Uniform;
    const bool rendered = scale_out_ && uniform  ? render_split()
                          : ranges_done_.empty() ? render_here()
                                                 : render_ranges_here();
    const bool ended = rendered && (!request_.denoise || denoise_result());
    if (!ended) {
      release(interrupt_requested() ? "interrupted" : "cancelled");
      return false;
    }
  } catch (const std::exception& e) {
    release("failed");
    spdlog::warn("render {} failed: {}", id(), e.what());
    throw;
  }
  release("done");
  return true;
}

bool RenderJob::render_here() {
  using Clock = std::chrono::steady_clock;
  const auto& s = request_.settings;
  render::Renderer renderer(request_.scene, request_.lighting, s, envmap_);
  auto passes = render::render_passes(s);
  const int earlier_spp = skip_done_passes(passes);
  if (earlier_spp > 0) {
    const RenderImage earlier = image();
    renderer.resume(*earlier.image, earlier_spp);
    for (const auto p : s.passes.list()) renderer.resume(p, *earlier.passes[size_t(p)]);
    spdlog::info("render {} continues after {} spp", id(), earlier_spp);
  }
  const int64_t tiles = renderer.tile_count();
  set_render_work(tiles * s.spp, tiles * earlier_spp);
  save_record();
  const auto start = Clock::now();
  int spp_done = earlier_spp;  // the passes' samples per pixel (an adaptive pass's are a mean)
  for (const render::RenderPass& pass : passes) {
    const auto on_tile = [this, spp = pass.spp] { add_work_done(spp); };
    if (interrupt_requested() || !renderer.render(pass, cancel_flag(), on_tile)) return false;
    spp_done += pass.spp;
    publish(renderer.image(), pass_images(s.passes, [&](render::AuxPass p) { return renderer.image(p); }),
            spp_done, renderer.stats(), std::chrono::duration<double>(Clock::now() - start).count());
    checkpoint();
  }
  return true;
}

std::vector<render::SampleRange> RenderJob::done_ranges() const {
  std::lock_guard lock(mutex_);
  if (!ranges_done_.empty()) return ranges_done_;
  if (spp_done_ == 0) return {};
  return {{0, uint32_t(spp_done_)}};
}

render::PartialFilm RenderJob::done_film() const {
  const auto& s = request_.settings;
  const RenderImage done = image();
  if (!done.image) return render::PartialFilm(s.width, s.height, s.passes);
  render::PartialFilm film = render::PartialFilm::from_mean(*done.image, uint32_t(done.spp_done), s.passes);
  for (const auto p : s.passes.list()) film.set_mean(p, *done.passes[size_t(p)]);
  return film;
}

struct RenderJob::RangeRun {
  using Clock = std::chrono::steady_clock;
  RangeRun(std::vector<render::SampleRange> done, int spp) : ranges(std::move(done)), spp_done(spp) {}
  std::vector<render::SampleRange> ranges;
  int spp_done = 0;
  render::RenderStats stats;
  Clock::time_point start = Clock::now(), kept = Clock::now();
};

void RenderJob::merged(RangeRun& run, const render::PartialFilm& film, render::SampleRange range,
                       uint64_t rays) {
  constexpr auto kKeepEvery = std::chrono::seconds(5);
  run.ranges.push_back(range);
  run.spp_done += range.count();
  run.stats.samples += uint64_t(range.count()) * film.pixel_count();
  run.stats.rays += rays;
  const auto now = RangeRun::Clock::now();
  publish(film.mean(), pass_images(film.passes(), [&](render::AuxPass p) { return film.mean(p); }),
          run.spp_done, run.stats, std::chrono::duration<double>(now - run.start).count(), run.ranges);
  if (now - run.kept < kKeepEvery) return;
  checkpoint();
  run.kept = now;
}

// Work items on Redis; the image of the ranges merged so far is published as they arrive.
bool RenderJob::render_split() {
  const auto& s = request_.settings;
  RangeRun run{done_ranges(), spp_done()};
  const auto items = render::ranges_outside(s.spp, scale_out_->item_spp, run.ranges);
  set_render_work(s.spp, run.spp_done);
  save_record();
  if (run.spp_done > 0) spdlog::info("render {} continues after {} spp", id(), run.spp_done);
  RenderCoordinator coordinator(*scale_out_, id());
  const RenderDescription description{request_json_, envmap_content_hash(*envmap_), scale_out_->advertise_url,
                                      scale_out_->bundles->publish(request_.scene)};
  const bool done = coordinator.run(
      description, items, done_film(), [this] { return interrupt_requested() || cancel_flag().load(); },
      [&](const render::PartialFilm& film, render::SampleRange range, uint64_t rays) {
        add_work_done(range.count());
        merged(run, film, range, rays);
      });
  if (done || interrupt_requested()) checkpoint();
  return done;
}

// A render split over Redis, continued without it: the ranges it lacks, rendered here.
bool RenderJob::render_ranges_here() {
  constexpr int kRangeSpp = 32;  // samples per pixel between published images, as render_here's passes
  const auto& s = request_.settings;
  render::Renderer renderer(request_.scene, request_.lighting, s, envmap_);
  RangeRun run{done_ranges(), spp_done()};
  auto film = done_film();
  const int64_t tiles = renderer.tile_count();
  set_render_work(tiles * s.spp, tiles * run.spp_done);
  save_record();
  spdlog::info("render {} continues here after {} spp", id(), run.spp_done);
  for (const auto range : render::ranges_outside(s.spp, kRangeSpp, run.ranges)) {
    const auto partial =
        interrupt_requested()
            ? std::nullopt
            : renderer.render_range(range, cancel_flag(), [this, range] { add_work_done(range.count()); });
    if (!partial) {
      if (interrupt_requested()) checkpoint();
      return false;
    }
    film.merge(partial->film);
    merged(run, film, range, partial->rays);
  }
  checkpoint();
  return true;
}

void RenderJob::set_render_work(int64_t total, int64_t done) {
  render_work_ = total;
  set_work(total + (request_.denoise ? denoise_work(total) : 0), done);
}

bool RenderJob::denoise_result() {
  using Clock = std::chrono::steady_clock;
  if (!denoiser_) throw std::logic_error("a render to denoise has no denoiser");
  const RenderImage done = image();
  const int64_t share = denoise_work(render_work_);
  denoise::DenoiseOptions options;
  options.progress = [&](double fraction) {
    set_work(render_work_ + share, render_work_ + int64_t(fraction * double(share)));
    return !cancel_flag().load() && !interrupt_requested();
  };
  const auto start = Clock::now();
  std::shared_ptr<const Image> denoised;
  try {
    denoised = std::make_shared<const Image>(denoiser_->run(
        {done.image.get(), done.pass(render::AuxPass::Albedo), done.pass(render::AuxPass::Normal)}, options));
  } catch (const denoise::DenoiseCancelled&) {
    return false;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  {
    std::lock_guard lock(mutex_);
    denoised_ = std::move(denoised);
    denoise_s_ = seconds;
  }
  spdlog::info("render {} denoised in {:.2f} s", id(), seconds);
  checkpoint();
  return true;
}

void RenderJob::describe(nlohmann::json& out) const {
  std::lock_guard lock(mutex_);
  api::describe_render(out, request_, {spp_done_, stats_, render_s_, image_ != nullptr, denoise_s_});
}

}  // namespace lp::server
