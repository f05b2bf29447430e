#include "tools/soak/soak_run.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#include "board/config/board_overrides.h"
#include "board/loop/live_loop.h"
#include "board/replay/bench_replay.h"
#include "drivers/clock/loop_clock.h"
#include "drivers/clock/monotonic_clock.h"
#include "drivers/replay/recording_reader.h"
#include "drivers/replay/replay_source.h"

namespace deepnav::soak {
namespace {

constexpr TimeUs kStartDelayUs = 200'000;  // recording time before the first sample (threads start)
constexpr TimeUs kDrainUs = 500'000;       // recording time after the last sample (last vision results)

// Stereo images are not recorded: at 10 pairs/s they are 7 MB/s of disk, and the soak is about memory.
const char* const kSoakOverrides[] = {"recording.record_images=false"};

double wallSince(TimeUs t0) { return usToS(monotonicUs() - t0); }

bool runDive(const SoakOptions& o, const std::string& path, int index, SoakDive* dive, std::string* error) {
  dive->index = index;
  dive->path = path;
  RecordingReader reader;
  if (!reader.open(path, error)) return false;
  VehicleSetup setup;
  if (!loadReplaySetup(o.board_path, reader, path, &setup, error)) return false;
  std::vector<std::string> overrides(std::begin(kSoakOverrides), std::end(kSoakOverrides));
  overrides.insert(overrides.end(), o.overrides.begin(), o.overrides.end());
  if (!applyBoardOverrides(overrides, &setup, error)) return false;
  const std::string recording = o.scratch_dir + "/soak-" + std::to_string(::getpid()) + ".mcap";
  auto loop = std::make_unique<LiveLoop>();
  if (!loop->init(setup, recording, error)) return false;
  ReplaySource source;
  if (!source.open(path, error)) return false;
  const TimeUs anchor = monotonicUs();
  const LoopClock clock = LoopClock::at(source.firstTimeUs() - kStartDelayUs - anchor, o.speed, anchor);
  if (!loop->start(clock, error)) return false;
  source.start(&loop->inputs(), clock);
  const TimeUs t0 = monotonicUs();
  const auto period = std::chrono::microseconds(sToUs(o.sample_period_s));
  while (!source.finished() || clock.toLoop(monotonicUs()) < source.lastTimeUs() + kDrainUs) {
    std::this_thread::sleep_for(period);
    dive->peak_rss_kib = std::max(dive->peak_rss_kib, residentKib());
  }
  source.stop();
  const bool closed = loop->stop(error);
  dive->wall_s = wallSince(t0);
  dive->dive_s = usToS(source.lastTimeUs() - source.firstTimeUs());
  const LoopStats s = loop->stats();
  const int nav = 0, vision = 2;  // LiveLoop's scheduler table: nav, stats, vision
  dive->ticks = s.ticks;
  dive->late_ticks = s.late_ticks;
  dive->max_lateness_us = s.max_lateness_us;
  dive->nav_overruns = s.overruns[nav];
  dive->nav_max_us = s.max_us[nav];
  dive->vision_runs = s.runs[vision];
  dive->vision_overruns = s.overruns[vision];
  dive->vision_max_us = s.max_us[vision];
  dive->refused = source.refused() + loop->inputsRefused();
  dive->recorder_drops = loop->recorderDrops();
  dive->final_stage = static_cast<int>(loop->latest().stage);
  if (!source.error().empty()) {
    if (error) *error = path + ": " + source.error();
    return false;
  }
  loop.reset();
  std::error_code ec;
  std::filesystem::remove(recording, ec);
  dive->end_rss_kib = residentKib();
  dive->peak_rss_kib = std::max(dive->peak_rss_kib, dive->end_rss_kib);
  return closed;
}

double slopePerHour(const std::vector<SoakDive>& dives, int first, const std::vector<double>& t_end_s) {
  const int n = static_cast<int>(dives.size()) - first;
  if (n < 2) return 0.0;
  double mt = 0, my = 0;
  for (int i = first; i < static_cast<int>(dives.size()); ++i) {
    mt += t_end_s[static_cast<std::size_t>(i)];
    my += dives[static_cast<std::size_t>(i)].end_rss_kib;
  }
  mt /= n;
  my /= n;
  double stt = 0, sty = 0;
  for (int i = first; i < static_cast<int>(dives.size()); ++i) {
    const double dt = t_end_s[static_cast<std::size_t>(i)] - mt;
    stt += dt * dt;
    sty += dt * (dives[static_cast<std::size_t>(i)].end_rss_kib - my);
  }
  return stt > 0 ? sty / stt * 3600.0 : 0.0;
}

// Dive peaks are bimodal after the warm-up (e.g. 169.3 or 170.7 MiB: one allocator region the next dive
// gives back), so one peak against another is noise. A leak raises both modes: the growth is how much the
// second half of the post-warm-up dives rose over the first, the smaller of the rise of the lowest peak
// (the floor) and of the highest (the ceiling). The floor alone reads the region's 1.4 MiB as growth when
// the low mode happens to show in the first half only (seen in CI: one low dive of five), the ceiling
// alone when the high mode does; a leak moves both.
double halfExtreme(const std::vector<SoakDive>& dives, std::size_t from, std::size_t to, bool lowest) {
  double v = dives[from].peak_rss_kib;
  for (std::size_t i = from; i < to; ++i) {
    v = lowest ? std::min(v, dives[i].peak_rss_kib) : std::max(v, dives[i].peak_rss_kib);
  }
  return v;
}

double floorGrowthKib(const std::vector<SoakDive>& dives, int warmup) {
  const std::size_t first = static_cast<std::size_t>(warmup);
  if (dives.size() < first + 2) return 0.0;
  const std::size_t mid = first + (dives.size() - first) / 2;
  const double floor_rise = halfExtreme(dives, mid, dives.size(), true) - halfExtreme(dives, first, mid, true);
  const double ceiling_rise = halfExtreme(dives, mid, dives.size(), false) - halfExtreme(dives, first, mid, false);
  return std::min(floor_rise, ceiling_rise);
}

}  // namespace

double residentKib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr);
  }
  return 0.0;
}

bool runSoak(const SoakOptions& o, SoakResult* r) {
  *r = SoakResult{};
  if (o.dives.empty()) {
    r->error = "no dive to replay";
    return false;
  }
  if (!(o.speed > 0.0 && o.speed <= 100.0)) {
    r->error = "--speed must be in (0, 100]";
    return false;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.scratch_dir, ec);
  const TimeUs t0 = monotonicUs();
  std::vector<double> t_end_s;
  for (int i = 0; i == 0 || wallSince(t0) < o.minutes * 60.0 || i < o.warmup_dives + 3; ++i) {
    SoakDive dive;
    const std::string& path = o.dives[static_cast<std::size_t>(i) % o.dives.size()];
    if (!runDive(o, path, i + 1, &dive, &r->error)) {
      r->wall_s = wallSince(t0);
      return false;
    }
    r->dives.push_back(dive);
    t_end_s.push_back(wallSince(t0));
    const bool warm = i < o.warmup_dives;
    if (warm) {
      r->baseline_rss_kib = std::max(r->baseline_rss_kib, dive.peak_rss_kib);
    } else {
      r->after_rss_kib = std::max(r->after_rss_kib, dive.peak_rss_kib);
    }
    if (o.progress) {
      std::fprintf(stderr, "soak: dive %d (%s) %.1f s in %.1f s wall, peak RSS %.1f MiB%s, %.1f of %.1f min\n",
                   dive.index, path.c_str(), dive.dive_s, dive.wall_s, dive.peak_rss_kib / 1024.0,
                   warm ? " (warm-up)" : "", wallSince(t0) / 60.0, o.minutes);
    }
  }
  r->wall_s = wallSince(t0);
  r->growth_kib = floorGrowthKib(r->dives, o.warmup_dives);
  r->end_rss_slope_kib_per_h = slopePerHour(r->dives, o.warmup_dives, t_end_s);
  r->growth_ok = r->growth_kib < o.max_growth_kib;
  return true;
}

std::string formatSoakTable(const SoakOptions& o, const SoakResult& r) {
  std::ostringstream out;
  char buf[512];
  out << "| dive | recording (s) | wall (s) | ticks | late | max late (ms) | nav overruns | nav max (us) | pairs | "
         "vision overruns | vision max (ms) | refused | recorder drops | stage | peak RSS (MiB) | end RSS (MiB) |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SoakDive& d : r.dives) {
    std::snprintf(buf, sizeof buf,
                  "| %d%s | %.1f | %.1f | %llu | %llu | %.1f | %llu | %lld | %llu | %llu | %.1f | %llu | %llu | %d | "
                  "%.2f | %.2f |\n",
                  d.index, d.index <= o.warmup_dives ? " (warm-up)" : "", d.dive_s, d.wall_s,
                  static_cast<unsigned long long>(d.ticks), static_cast<unsigned long long>(d.late_ticks),
                  d.max_lateness_us / 1000.0, static_cast<unsigned long long>(d.nav_overruns),
                  static_cast<long long>(d.nav_max_us), static_cast<unsigned long long>(d.vision_runs),
                  static_cast<unsigned long long>(d.vision_overruns), d.vision_max_us / 1000.0,
                  static_cast<unsigned long long>(d.refused), static_cast<unsigned long long>(d.recorder_drops),
                  d.final_stage, d.peak_rss_kib / 1024.0, d.end_rss_kib / 1024.0);
    out << buf;
  }
  std::uint64_t late = 0, nav_over = 0, vis_over = 0, refused = 0;
  double replayed_s = 0;
  for (const SoakDive& d : r.dives) {
    late += d.late_ticks;
    nav_over += d.nav_overruns;
    vis_over += d.vision_overruns;
    refused += d.refused;
    replayed_s += d.dive_s;
  }
  std::snprintf(buf, sizeof buf,
                "\nsoak: %zu dives, %.1f min of recordings in %.1f min wall (%.2fx real time, loop clock at %.2fx)\n"
                "late ticks %llu, nav overruns %llu, vision overruns %llu, refused samples/frames %llu\n"
                "resident memory: warm-up (%d dives) peak %.2f MiB, highest after warm-up %.2f MiB; growth after "
                "warm-up (second half - first half, the lesser rise of the lowest and the highest dive peak) %+.0f KiB "
                "(limit %.0f KiB), "
                "end-of-dive trend %+.0f KiB/h: %s\n",
                r.dives.size(), replayed_s / 60.0, r.wall_s / 60.0, r.wall_s > 0 ? replayed_s / r.wall_s : 0.0,
                o.speed, static_cast<unsigned long long>(late), static_cast<unsigned long long>(nav_over),
                static_cast<unsigned long long>(vis_over), static_cast<unsigned long long>(refused), o.warmup_dives,
                r.baseline_rss_kib / 1024.0, r.after_rss_kib / 1024.0, r.growth_kib, o.max_growth_kib,
                r.end_rss_slope_kib_per_h, r.growth_ok ? "PASS" : "FAIL");
  out << buf;
  return out.str();
}

std::string soakJson(const SoakOptions& o, const SoakResult& r) {
  std::ostringstream out;
  out << "{\"speed\": " << o.speed << ", \"warmup_dives\": " << o.warmup_dives << ", \"wall_s\": " << r.wall_s
      << ", \"baseline_rss_kib\": " << r.baseline_rss_kib << ", \"after_rss_kib\": " << r.after_rss_kib
      << ", \"growth_kib\": " << r.growth_kib << ", \"max_growth_kib\": " << o.max_growth_kib
      << ", \"end_rss_slope_kib_per_h\": " << r.end_rss_slope_kib_per_h
      << ", \"growth_ok\": " << (r.growth_ok ? "true" : "false") << ", \"dives\": [";
  for (std::size_t i = 0; i < r.dives.size(); ++i) {
    const SoakDive& d = r.dives[i];
    out << (i ? ", " : "") << "{\"index\": " << d.index << ", \"dive_s\": " << d.dive_s << ", \"wall_s\": " << d.wall_s
        << ", \"ticks\": " << d.ticks << ", \"late_ticks\": " << d.late_ticks << ", \"nav_overruns\": " << d.nav_overruns
        << ", \"vision_runs\": " << d.vision_runs << ", \"vision_overruns\": " << d.vision_overruns
        << ", \"refused\": " << d.refused << ", \"recorder_drops\": " << d.recorder_drops
        << ", \"final_stage\": " << d.final_stage << ", \"peak_rss_kib\": " << d.peak_rss_kib
        << ", \"end_rss_kib\": " << d.end_rss_kib << "}";
  }
  out << "]}\n";
  return out.str();
}

}  // namespace deepnav::soak
