// extraction.cpp - stage 2 of the pipeline (pipeline.h): the sun (light_extraction.h) or the
// lights (light_candidates.h, chosen by light_choice.h, fitted by light_fit.h) taken out of
// a whole equirect map.
#include <utility>
#include <new>
#include <vector>

#include "shpack/light_fit.h"
#include "shpack/pipeline.h"

namespace shpack {
namespace {

// Y = w . (M rgb) = (M^T w) . rgb: the luminance of the output primaries (light_extraction.h).
SunSearch search_of(const ConvertOptions& options) noexcept {
  SunSearch search{kRec709Luminance, options.negative};
  if (const std::optional<Matrix3>& m = options.finish.colour_matrix) {
    for (int j = 0; j < 3; ++j)
      search.luminance[j] = kRec709Luminance[0] * (*m)[0][j] + kRec709Luminance[1] * (*m)[1][j] +
                            kRec709Luminance[2] * (*m)[2][j];
  }
  return search;
}

// The fixed band factors of the finish stage (light_fit.h): a band-scaling window's, band 2
// removed by --l1; sloan and optimal depend on the data and are left to the measure.
std::array<double, 3> band_factors_of(const FinishOptions& finish) noexcept {
  std::array<double, 3> f = {1.0, 1.0, 1.0};
  if (finish.window.kind != WindowKind::Sloan && finish.window.kind != WindowKind::Optimal &&
      !window_factors(finish.window, f).ok())
    f = {1.0, 1.0, 1.0};  // an invalid window is refused by the finish stage itself
  if (finish.l1) f[2] = 0.0;
  return f;
}

// The measure of light_choice.h: the max error of what Unity shows with the candidates
// `chosen` as lights (light_fit.h: their colours fitted, the SH the map's exact projection
// less theirs), and its settling step, which moves the chosen lights' directions.
class ChoiceMeasure {
 public:
  // `problem`: the fit of the map whose exact projection is `projected` (prepare_light_fit).
  ChoiceMeasure(const ShL2& projected, const LightFitProblem& problem, std::span<const LightCandidate> candidates,
                const FinishOptions& finish)
      : projected_(projected), problem_(problem), candidates_(candidates), finish_(finish),
        transform_{finish.colour_matrix, finish.intensity, finish.rotate_deg} {}

  // The error with `chosen` as lights: the settled ones at their settled directions, the
  // others at their sources' centres.
  Status operator()(std::span<const std::size_t> chosen, double& error) {
    try {
      set_lights(chosen);
      return fit_and_measure(error);
    } catch (const std::bad_alloc&) {
      return Status::error(Errc::OutOfMemory, "out of memory fitting the lights");
    }
  }

  // light_choice.h's settling: the directions of `chosen` refined (refine_light_directions)
  // from where they are and afresh from their sources' centres (a joint search from the
  // centres can find what moving one light at a time cannot, and the other way round), the
  // better kept for the next steps when it lowers the measured error.
  Status settle(std::span<const std::size_t> chosen, double& error) {
    try {
      set_lights(chosen);
      settled_.assign(chosen.begin(), chosen.end());
      settled_directions_ = directions_;
      for (const std::vector<Dir3>* start : {&settled_directions_, &sources_}) {
        std::vector<Dir3> refined = *start;
        if (Status st = refine_light_directions(problem_, sources_, reach_deg_, refined); !st.ok())
          return st;
        directions_ = refined;
        double refined_error = 0;
        if (Status st = fit_and_measure(refined_error); !st.ok()) return st;
        if (refined_error < error) settled_directions_ = std::move(refined), error = refined_error;
      }
      return Status::success();
    } catch (const std::bad_alloc&) {
      return Status::error(Errc::OutOfMemory, "out of memory refining the lights");
    }
  }

  // The lights and their SH for the last set measured.
  const std::vector<SunLight>& lights() const noexcept { return lights_; }
  const ShL2& removed() const noexcept { return removed_; }

 private:
  // Directions, sources and limits of `chosen` (light_fit.h: a light stays within
  // kLightReachRadii of its source's radius plus kLightReachDeg of its centre).
  void set_lights(std::span<const std::size_t> chosen) {
    directions_.clear(), sources_.clear(), reach_deg_.clear();
    for (std::size_t j = 0; j < chosen.size(); ++j) {
      const SunLight& source = candidates_[chosen[j]].light;
      const bool settled = j < settled_.size() && settled_[j] == chosen[j];
      directions_.push_back(settled ? settled_directions_[j] : source.direction);
      sources_.push_back(source.direction);
      reach_deg_.push_back(light_reach_deg(source.radius_deg));
    }
    chosen_.assign(chosen.begin(), chosen.end());
  }

  Status fit_and_measure(double& error) {
    LightFit fit;
    if (Status st = fit_light_colours(problem_, directions_, fit); !st.ok()) return st;
    lights_.clear();
    for (std::size_t j = 0; j < chosen_.size(); ++j) {
      lights_.push_back(candidates_[chosen_[j]].light);
      lights_.back().direction = directions_[j];
      lights_.back().irradiance = fit.irradiance[j];
      lights_.back().offset_deg = angle_deg(directions_[j], sources_[j]);
    }
    removed_ = fitted_lights_sh(directions_, fit);
    ShL2 rest = projected_;
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) rest.c[c][i] -= removed_.c[c][i];
    FinishedSh sh;
    if (Status st = finish_projection(rest, finish_, sh); !st.ok()) return st;
    shown_.clear();
    for (const SunLight& light : lights_) shown_.push_back(finish_light(light, finish_).unity);
    error = unity_view_error(*problem_.samples, transform_, sh.shader, shown_).max_pct;
    return Status::success();
  }

  const ShL2& projected_;
  const LightFitProblem& problem_;
  std::span<const LightCandidate> candidates_;
  const FinishOptions& finish_;
  ViewTransform transform_;
  std::vector<std::size_t> chosen_, settled_;  // the set measured; the prefix settled
  std::vector<Dir3> directions_, sources_, settled_directions_;
  std::vector<double> reach_deg_;
  std::vector<SunLight> lights_;
  ShL2 removed_;
  std::vector<UnitySunLight> shown_;
};

Status extract_lights(const MapImage& map, const ConvertOptions& options, const ViewSamples& reference,
                      Extraction& out) noexcept {
  std::vector<LightCandidate> candidates;
  if (Status st = find_light_candidates_at_scales(map.image, search_of(options), kLightCandidateCount,
                                                  kLightChoiceScales, candidates);
      !st.ok())
    return st;
  ShL2 projected;
  const ProjectOptions exact{SamplingMethod::Exact, NonFinite::Zero, options.negative, options.threads};
  if (Status st = project_equirect(map.image, exact, projected); !st.ok()) return st;
  Extraction result;
  try {
    LightFitProblem problem;
    if (Status st = prepare_light_fit(reference, projected, band_factors_of(options.finish), problem); !st.ok())
      return st;
    ChoiceMeasure measure(projected, problem, candidates, options.finish);
    auto settle = [&measure](std::span<const std::size_t> chosen, double& error) {
      return measure.settle(chosen, error);
    };
    if (Status st = choose_lights(candidates, options.extract_lights, measure, result.choice, settle); !st.ok())
      return st;
    std::vector<std::size_t> chosen;
    for (const ChosenLight& light : result.choice.lights) chosen.push_back(light.candidate);
    double error = 0;  // the lights as the last step settled them
    if (Status st = measure(chosen, error); !st.ok()) return st;
    result.lights = measure.lights();
    result.removed = measure.removed();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory choosing the lights to extract");
  }
  result.candidates = candidates.size();
  out = std::move(result);
  return Status::success();
}

}  // namespace

Status extract_from_map(const MapImage& map, const ConvertOptions& options, const ViewSamples& reference,
                        Extraction& out) noexcept {
  if (options.extract_lights > 0) return extract_lights(map, options, reference, out);
  Extraction result;
  if (options.extract_sun) {
    if (Status st = extract_sun(map.image, map.writable, search_of(options), result.sun); !st.ok()) return st;
  }
  out = std::move(result);
  return Status::success();
}

}  // namespace shpack
