// c_api.cpp - the first version's entry points of the C ABI (shpack_c.h): equirect maps, whole
// or streamed, and the shader; shpack_convert is in c_api_convert.cpp.
// Every function is noexcept in effect: the core never throws, and the only allocation here
// (the projector handle) uses nothrow new.
#include "shpack/shpack_c.h"

#include <new>
#include <utility>

#include "c_api_common.h"
#include "shpack/pipeline.h"

struct shpack_projector {
  shpack::EquirectProjector projector;
  shpack::ViewReference reference;  // the truth that the result's view error is measured against
  shpack::FinishOptions finish;
  unsigned threads = 1;  // shpack_options.threads, for the reference's directions too
  bool finished = false;
  shpack_view_error view_error{};  // of the finished result
};

namespace {

using shpack::Errc;
using shpack::Status;
using shpack::c_api::invalid;
using shpack::c_api::report;
using shpack::c_api::result_of;
using shpack::c_api::to_policies;
using shpack::c_api::to_view;

// The pipeline's options (pipeline.h) of a shpack_options.
Status to_options(const shpack_options& options, shpack::ConvertOptions& out) {
  if (options.method != SHPACK_METHOD_EXACT && options.method != SHPACK_METHOD_CENTER)
    return Status::error(Errc::InvalidArgument, "method must be SHPACK_METHOD_EXACT or SHPACK_METHOD_CENTER");
  shpack::ConvertOptions result;
  if (Status st = to_policies(options.nonfinite, options.negative, result); !st.ok()) return st;
  result.method.method =
      options.method == SHPACK_METHOD_EXACT ? shpack::SamplingMethod::Exact : shpack::SamplingMethod::Center;
  result.threads = options.threads;
  result.finish.intensity = options.intensity;
  result.finish.rotate_deg = options.rotate_deg;
  if (options.window != nullptr) {
    if (Status st = shpack::parse_window(options.window, result.finish.window); !st.ok()) return st;
  }
  out = result;
  return Status::success();
}

}  // namespace

extern "C" {

int32_t shpack_abi_version(void) { return SHPACK_C_ABI_VERSION; }

const char* shpack_version(void) { return SHPACK_VERSION; }

const char* shpack_status_name(int32_t code) {
  switch (code) {
    case SHPACK_OK: return "ok";
    case SHPACK_INVALID_ARGUMENT: return "invalid_argument";
    case SHPACK_BAD_VIEW: return "bad_view";
    case SHPACK_NONFINITE_TEXEL: return "nonfinite_texel";
    case SHPACK_BAD_SEQUENCE: return "bad_sequence";
    case SHPACK_OUT_OF_MEMORY: return "out_of_memory";
    case SHPACK_OUT_OF_RANGE: return "out_of_range";
    case SHPACK_INTERNAL: return "internal";
    default: return "unknown";
  }
}

void shpack_default_options(shpack_options* options) {
  if (options != nullptr)
    *options = {SHPACK_METHOD_EXACT, SHPACK_NONFINITE_ERROR, SHPACK_NEGATIVE_KEEP, 0, 1.0, 0.0, nullptr};
}

int32_t shpack_convert_equirect(const shpack_image* image, const shpack_options* options, shpack_result* result,
                                shpack_error* error) {
  if (image == nullptr || options == nullptr || result == nullptr)
    return invalid("image, options and result must not be NULL", error);
  shpack::ConvertOptions convert;
  if (Status st = to_options(*options, convert); !st.ok()) return report(st, error);
  shpack::MapImage map;
  if (Status st = to_view(*image, map.image); !st.ok()) return report(st, error);
  shpack::Conversion conversion;
  if (Status st = shpack::convert_map(map, convert, conversion); !st.ok()) return report(st, error);
  *result = result_of(conversion);
  return report(Status::success(), error);
}

int32_t shpack_projector_create(uint32_t width, uint32_t height, const shpack_options* options,
                                shpack_projector** projector, shpack_error* error) {
  if (options == nullptr || projector == nullptr) return invalid("options and projector must not be NULL", error);
  *projector = nullptr;
  shpack::ConvertOptions convert;
  if (Status st = to_options(*options, convert); !st.ok()) return report(st, error);
  auto* p = new (std::nothrow) shpack_projector;
  if (p == nullptr) return report(Status::error(Errc::OutOfMemory, "cannot allocate the projector"), error);
  p->finish = convert.finish;
  p->threads = convert.threads;
  // Stage 3 streamed by the caller, with its value policies applied as the rows arrive.
  const shpack::ProjectOptions project{convert.method.method, convert.nonfinite, convert.negative, convert.threads};
  if (Status st = p->projector.begin(width, height, project); !st.ok()) {
    delete p;
    return report(st, error);
  }
  if (Status st = p->reference.begin_equirect(width, height, project); !st.ok()) {
    delete p;
    return report(st, error);
  }
  *projector = p;
  return report(Status::success(), error);
}

int32_t shpack_projector_add_rows(shpack_projector* projector, const shpack_image* rows, uint32_t first_row,
                                  shpack_error* error) {
  if (projector == nullptr || rows == nullptr) return invalid("projector and rows must not be NULL", error);
  shpack::ImageView view;
  if (Status st = to_view(*rows, view); !st.ok()) return report(st, error);
  if (Status st = projector->projector.add_rows(view, first_row); !st.ok()) return report(st, error);
  return report(projector->reference.add_rows(view, first_row), error);
}

int32_t shpack_projector_finish(shpack_projector* projector, shpack_result* result, shpack_error* error) {
  if (projector == nullptr || result == nullptr) return invalid("projector and result must not be NULL", error);
  if (projector->finished)
    return report(Status::error(Errc::BadSequence, "the projector was already finished"), error);
  shpack::ShL2 radiance;
  shpack::ProjectStats stats;
  if (Status st = projector->projector.finish(radiance, &stats); !st.ok()) return report(st, error);
  projector->finished = true;
  shpack::ViewSamples samples;
  if (Status st = projector->reference.finish(); !st.ok()) return report(st, error);
  if (Status st = shpack::sample_view_reference(std::move(projector->reference), samples, projector->threads); !st.ok())
    return report(st, error);
  shpack::Conversion conversion;
  if (Status st = shpack::finish_conversion(radiance, stats, shpack::Extraction{}, projector->finish, &samples, conversion); !st.ok())
    return report(st, error);
  *result = result_of(conversion);
  projector->view_error = shpack::c_api::view_error_of(conversion);
  return report(Status::success(), error);
}

int32_t shpack_projector_view_error(const shpack_projector* projector, shpack_view_error* view_error,
                                    shpack_error* error) {
  if (projector == nullptr || view_error == nullptr) return invalid("projector and view_error must not be NULL", error);
  if (!projector->finished || projector->view_error.directions == 0)
    return report(Status::error(Errc::BadSequence, "the projector has not finished"), error);
  *view_error = projector->view_error;
  return report(Status::success(), error);
}

void shpack_projector_destroy(shpack_projector* projector) { delete projector; }

int32_t shpack_shade_sh9(const float shader[28], float x, float y, float z, float rgb[3]) {
  if (shader == nullptr || rgb == nullptr) return SHPACK_INVALID_ARGUMENT;
  shpack::UnityShaderVectors v;
  shpack::UnityShaderVectors::Float4* vectors[7] = {&v.SHAr, &v.SHAg, &v.SHAb, &v.SHBr, &v.SHBg, &v.SHBb, &v.SHC};
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 4; ++j) (*vectors[k])[j] = shader[4 * k + j];
  for (int c = 0; c < 3; ++c) rgb[c] = shpack::shade_sh9(v, c, x, y, z);
  return SHPACK_OK;
}

}  // extern "C"
