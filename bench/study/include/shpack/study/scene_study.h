// scene_study.h - what accuracy costs in time for a scene (`shpack bench SCENE.json`).
//
// Each Monte Carlo effect of the scene (shadows, sky_occlusion, emission, bounce) is baked at
// fixed sample counts by both of the bake's estimators (bake.h, BakeOptions::next_events:
// with next-event estimation and multiple importance sampling, "next-events"; the directions'
// own strategies alone, "directions", the design the bake had before), over several seeds,
// and once at the scene's own settings ("settings": its target_error_pct and max_samples).
// Each effect's part of each probe is compared with the same part of a reference bake of
// the same scene at many more samples (next events, another seed): the error of E/pi, the
// max over 1024 directions (accuracy.h), in % of the probe's mean E/pi in the reference, the
// worst probe; against the effect's own CPU time (its pass, all threads: what it costs, and
// what a loaded machine disturbs least).
//
// A scene with lightmaps is studied twice: its probes (if any), and its lightmaps' texels
// (lightmap_bake.h), each lightmap at most lightmap_side texels a side, the same way, texel
// for texel (the Baked texels of both bakes: dilated and padded ones only copy). Each record
// also gives the receivers per second of the whole bake (wall time, every effect).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"

namespace shpack::study {

struct SceneStudySettings {
  std::vector<int> counts = {64, 256, 1024, 4096};  // samples per probe or texel point (per light)
  unsigned seeds = 4;                               // bakes per count and estimator
  int reference_samples = 65536;
  unsigned threads = 0;                             // 0: all cores
  std::uint32_t lightmap_side = 16;                 // each lightmap at most this many texels a side
};

enum class Receiver { Probes, Texels };

struct SceneStudyRecord {
  std::string scene;      // the file's name
  std::string receivers;  // "probes", or "texels" (of every lightmap, at the study's size)
  std::size_t count = 0;  // receivers measured (texels: those baked, not dilated or padded)
  std::string effect;     // "shadows", "sky_occlusion", "emission", "bounce"
  std::string estimator;  // "next-events", "directions", "settings"
  double samples = 0;     // per probe: the fixed count, or for "settings" the mean taken
  unsigned seeds = 0;
  double cpu_ms = 0;     // median over the seeds of the effect's CPU time (all threads: the cost)
  double per_s = 0;      // median over the seeds of receivers per second of the whole bake's wall time
  // Over the seeds, of the worst probe's error (% of its mean E/pi): the RMS (the expected
  // error) and the largest; and the worst probe's own error estimate, its mean over the seeds.
  double err_max_pct = 0, err_worst_pct = 0, estimate_pct = 0;
  // The reference's own error estimate, its worst receiver: the floor below which a measured
  // error is the reference's noise rather than the run's.
  double reference_estimate_pct = 0;
};

// Runs the study; records in the order effect, estimator, count. `progress` (may be empty)
// is called after each record.
io::IoStatus run_scene_study(const std::filesystem::path& scene_file, const SceneStudySettings& settings,
                             std::vector<SceneStudyRecord>& records,
                             const std::function<void(const SceneStudyRecord&)>& progress);

// Each (scene, receivers, effect) has a Pareto front (pareto_front.h) over cpu_ms and
// err_max_pct: for a CPU-time budget, the estimator and samples with the least error. Its
// errors are sampled (RMS over `seeds` bakes). Beside each record, measured / estimate is
// err_max_pct / estimate_pct: how the bake's own estimate compares with what was measured.

// Markdown: one table of every record, then one table per front.
std::string scene_markdown_report(const std::vector<SceneStudyRecord>& records);
// A JSON array, one object per record, with the keys scene, receivers, count, effect,
// estimator, samples, seeds, cpu_ms, err_max_pct, err_worst_pct, error_estimate_pct
// (estimate_pct), reference_estimate_pct, receivers_per_s, measured_over_estimate (null
// without an estimate), error_kind ("sampled") and on_front (whether the record is a point
// of its front). Ends with a line break.
std::string scene_json_report(const std::vector<SceneStudyRecord>& records);
// The gnuplot commands that draw error against time, one panel per effect with its front
// behind one line per estimator, into `png` and then `svg` (run_gnuplot in gnuplot.h runs
// them).
std::string scene_plot_script(const std::vector<SceneStudyRecord>& records, const std::filesystem::path& png,
                              const std::filesystem::path& svg);

}  // namespace shpack::study
