// c_api.cpp - the C ABI (shpack_c.h) over the core: plain structs in, plain structs out.
// Every function is noexcept in effect: the core never throws, and the only allocation here
// (the projector handle) uses nothrow new.
#include "shpack/shpack_c.h"

#include <new>

#include "shpack/pipeline.h"

struct shpack_projector {
  shpack::EquirectProjector projector;
  shpack::FinishOptions finish;
  bool finished = false;
};

namespace {

using shpack::Errc;
using shpack::Status;

int32_t code_of(Errc code) {
  switch (code) {
    case Errc::Ok: return SHPACK_OK;
    case Errc::InvalidArgument: return SHPACK_INVALID_ARGUMENT;
    case Errc::BadView: return SHPACK_BAD_VIEW;
    case Errc::NonFiniteTexel: return SHPACK_NONFINITE_TEXEL;
    case Errc::BadSequence: return SHPACK_BAD_SEQUENCE;
    case Errc::OutOfMemory: return SHPACK_OUT_OF_MEMORY;
    case Errc::OutOfRange: return SHPACK_OUT_OF_RANGE;
    default: return SHPACK_INTERNAL;
  }
}

int32_t report(const Status& st, shpack_error* error) {
  const int32_t code = code_of(st.code);
  if (error != nullptr) *error = {code, st.x, st.y, st.face, st.what};
  return code;
}

int32_t invalid(const char* what, shpack_error* error) {
  return report(Status::error(Errc::InvalidArgument, what), error);
}

// The core's view of a shpack_image (0 strides mean packed).
Status to_view(const shpack_image& image, shpack::ImageView& view) {
  if (image.pixel_type != SHPACK_PIXEL_F32 && image.pixel_type != SHPACK_PIXEL_F16)
    return Status::error(Errc::InvalidArgument, "pixel_type must be SHPACK_PIXEL_F32 or SHPACK_PIXEL_F16");
  view = {static_cast<const std::byte*>(image.data),
          image.pixel_type == SHPACK_PIXEL_F32 ? shpack::PixelType::F32 : shpack::PixelType::F16,
          image.width,
          image.height,
          image.channels,
          image.pixel_stride == 0 ? shpack::kAutoStride : image.pixel_stride,
          image.row_stride == 0 ? shpack::kAutoStride : image.row_stride};
  return shpack::resolve_view(view);
}

// The pipeline's options (pipeline.h) of a shpack_options.
Status to_options(const shpack_options& options, shpack::ConvertOptions& out) {
  if (options.method != SHPACK_METHOD_EXACT && options.method != SHPACK_METHOD_CENTER)
    return Status::error(Errc::InvalidArgument, "method must be SHPACK_METHOD_EXACT or SHPACK_METHOD_CENTER");
  if (options.nonfinite != SHPACK_NONFINITE_ERROR && options.nonfinite != SHPACK_NONFINITE_ZERO)
    return Status::error(Errc::InvalidArgument, "nonfinite must be SHPACK_NONFINITE_ERROR or SHPACK_NONFINITE_ZERO");
  if (options.negative != SHPACK_NEGATIVE_KEEP && options.negative != SHPACK_NEGATIVE_CLAMP)
    return Status::error(Errc::InvalidArgument, "negative must be SHPACK_NEGATIVE_KEEP or SHPACK_NEGATIVE_CLAMP");
  shpack::ConvertOptions result;
  result.method.method =
      options.method == SHPACK_METHOD_EXACT ? shpack::SamplingMethod::Exact : shpack::SamplingMethod::Center;
  result.nonfinite = options.nonfinite == SHPACK_NONFINITE_ERROR ? shpack::NonFinite::Error : shpack::NonFinite::Zero;
  result.negative = options.negative == SHPACK_NEGATIVE_KEEP ? shpack::Negative::Keep : shpack::Negative::Clamp;
  result.threads = options.threads;
  result.finish.intensity = options.intensity;
  result.finish.rotate_deg = options.rotate_deg;
  if (options.window != nullptr) {
    if (Status st = shpack::parse_window(options.window, result.finish.window); !st.ok()) return st;
  }
  out = result;
  return Status::success();
}

// The result record of a conversion.
shpack_result result_of(const shpack::Conversion& conversion) {
  const shpack::FinishedSh& sh = conversion.sh;
  shpack_result out{};
  const shpack::UnitySphericalHarmonicsL2& unity = sh.unity_sh;
  const shpack::UnityShaderVectors& v = sh.shader;
  const shpack::UnityShaderVectors::Float4* vectors[7] = {&v.SHAr, &v.SHAg, &v.SHAb, &v.SHBr, &v.SHBg, &v.SHBb, &v.SHC};
  for (int c = 0; c < shpack::kChannelCount; ++c) {
    for (int i = 0; i < shpack::kShCount; ++i) {
      out.radiance_sh[9 * c + i] = sh.radiance.c[c][i];
      out.unity_sh[9 * c + i] = unity[c][i];
    }
    out.min_e_over_pi[c] = sh.min_e_over_pi[c].value;
    out.min_direction[3 * c] = sh.min_e_over_pi[c].direction.x;
    out.min_direction[3 * c + 1] = sh.min_e_over_pi[c].direction.y;
    out.min_direction[3 * c + 2] = sh.min_e_over_pi[c].direction.z;
    for (int l = 0; l < 3; ++l) out.window_factors[3 * c + l] = sh.window.factors[c][l];
  }
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 4; ++j) out.shader[4 * k + j] = (*vectors[k])[j];
  out.nonfinite_texels = conversion.stats.nonfinite_texels;
  out.negative_texels = conversion.stats.negative_texels;
  return out;
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
  // Stage 3 streamed by the caller, with its value policies applied as the rows arrive.
  const shpack::ProjectOptions project{convert.method.method, convert.nonfinite, convert.negative, convert.threads};
  if (Status st = p->projector.begin(width, height, project); !st.ok()) {
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
  return report(projector->projector.add_rows(view, first_row), error);
}

int32_t shpack_projector_finish(shpack_projector* projector, shpack_result* result, shpack_error* error) {
  if (projector == nullptr || result == nullptr) return invalid("projector and result must not be NULL", error);
  if (projector->finished)
    return report(Status::error(Errc::BadSequence, "the projector was already finished"), error);
  shpack::ShL2 radiance;
  shpack::ProjectStats stats;
  if (Status st = projector->projector.finish(radiance, &stats); !st.ok()) return report(st, error);
  projector->finished = true;
  shpack::Conversion conversion;
  if (Status st = shpack::finish_conversion(radiance, stats, std::nullopt, projector->finish, conversion); !st.ok())
    return report(st, error);
  *result = result_of(conversion);
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
