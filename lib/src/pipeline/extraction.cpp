// extraction.cpp - stage 2 of the pipeline (pipeline.h): the sun (light_extraction.h) or the
// lights (light_candidates.h, chosen by light_choice.h) taken out of a whole equirect map.
#include <iterator>
#include <new>
#include <vector>

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

// The measure of light_choice.h: the max error of what Unity shows with `chosen` taken out.
// The map's exact projection less their removed SH is the projection of the map with them
// removed (light_candidates.h), so no candidate is ever projected twice.
class ChoiceMeasure {
 public:
  ChoiceMeasure(const ShL2& projected, std::span<const LightCandidate> candidates, const FinishOptions& finish,
                const ViewSamples& reference)
      : projected_(projected), candidates_(candidates), finish_(finish), reference_(reference),
        transform_{finish.colour_matrix, finish.intensity, finish.rotate_deg} {
    lights_.reserve(candidates.size());
  }

  Status operator()(std::span<const std::size_t> chosen, double& error) {
    ShL2 rest = projected_;
    lights_.clear();
    for (std::size_t k : chosen) {
      for (int c = 0; c < kChannelCount; ++c)
        for (int i = 0; i < kShCount; ++i) rest.c[c][i] -= candidates_[k].removed.c[c][i];
      lights_.push_back(finish_light(candidates_[k].light, finish_).unity);
    }
    FinishedSh sh;
    if (Status st = finish_projection(rest, finish_, sh); !st.ok()) return st;
    error = unity_view_error(reference_, transform_, sh.shader, lights_).max_pct;
    return Status::success();
  }

 private:
  const ShL2& projected_;
  std::span<const LightCandidate> candidates_;
  const FinishOptions& finish_;
  const ViewSamples& reference_;
  ViewTransform transform_;
  std::vector<UnitySunLight> lights_;  // reserved for every candidate: push_back never allocates
};

Status extract_lights(const MapImage& map, const ConvertOptions& options, const ViewSamples& reference,
                      Extraction& out) noexcept {
  std::vector<LightCandidate> candidates, found;
  for (const LightScale& scale : kLightChoiceScales) {
    if (Status st = find_light_candidates(map.image, search_of(options), kLightCandidateCount, found, scale); !st.ok())
      return st;
    try {
      candidates.insert(candidates.end(), std::make_move_iterator(found.begin()), std::make_move_iterator(found.end()));
    } catch (const std::bad_alloc&) {
      return Status::error(Errc::OutOfMemory, "out of memory gathering the light candidates");
    }
  }
  ShL2 projected;
  const ProjectOptions exact{SamplingMethod::Exact, NonFinite::Zero, options.negative, options.threads};
  if (Status st = project_equirect(map.image, exact, projected); !st.ok()) return st;
  Extraction result;
  try {
    ChoiceMeasure measure(projected, candidates, options.finish, reference);
    if (Status st = choose_lights(candidates, options.extract_lights, measure, result.choice); !st.ok()) return st;
    std::vector<std::size_t> chosen;
    for (const ChosenLight& light : result.choice.lights) {
      chosen.push_back(light.candidate);
      result.lights.push_back(candidates[light.candidate].light);
    }
    if (Status st = remove_light_candidates(map.image, map.writable, candidates, chosen); !st.ok()) return st;
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
