// c_api_common.cpp - the conversions every C ABI entry point shares (c_api_common.h).
#include "c_api_common.h"

namespace shpack::c_api {
namespace {

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

}  // namespace

int32_t report(const Status& st, shpack_error* error) {
  const int32_t code = code_of(st.code);
  if (error != nullptr) *error = {code, st.x, st.y, st.face, st.what};
  return code;
}

int32_t invalid(const char* what, shpack_error* error) {
  return report(Status::error(Errc::InvalidArgument, what), error);
}

Status to_view(const shpack_image& image, ImageView& view) {
  if (image.pixel_type != SHPACK_PIXEL_F32 && image.pixel_type != SHPACK_PIXEL_F16)
    return Status::error(Errc::InvalidArgument, "pixel_type must be SHPACK_PIXEL_F32 or SHPACK_PIXEL_F16");
  view = {static_cast<const std::byte*>(image.data),
          image.pixel_type == SHPACK_PIXEL_F32 ? PixelType::F32 : PixelType::F16,
          image.width,
          image.height,
          image.channels,
          image.pixel_stride == 0 ? kAutoStride : image.pixel_stride,
          image.row_stride == 0 ? kAutoStride : image.row_stride};
  return resolve_view(view);
}

Status to_policies(int32_t nonfinite, int32_t negative, ConvertOptions& out) {
  if (nonfinite != SHPACK_NONFINITE_ERROR && nonfinite != SHPACK_NONFINITE_ZERO)
    return Status::error(Errc::InvalidArgument, "nonfinite must be SHPACK_NONFINITE_ERROR or SHPACK_NONFINITE_ZERO");
  if (negative != SHPACK_NEGATIVE_KEEP && negative != SHPACK_NEGATIVE_CLAMP)
    return Status::error(Errc::InvalidArgument, "negative must be SHPACK_NEGATIVE_KEEP or SHPACK_NEGATIVE_CLAMP");
  out.nonfinite = nonfinite == SHPACK_NONFINITE_ERROR ? NonFinite::Error : NonFinite::Zero;
  out.negative = negative == SHPACK_NEGATIVE_KEEP ? Negative::Keep : Negative::Clamp;
  return Status::success();
}

shpack_result result_of(const Conversion& conversion) {
  const FinishedSh& sh = conversion.sh;
  shpack_result out{};
  const UnitySphericalHarmonicsL2& unity = sh.unity_sh;
  const UnityShaderVectors& v = sh.shader;
  const UnityShaderVectors::Float4* vectors[7] = {&v.SHAr, &v.SHAg, &v.SHAb, &v.SHBr, &v.SHBg, &v.SHBb, &v.SHC};
  for (int c = 0; c < kChannelCount; ++c) {
    for (int i = 0; i < kShCount; ++i) {
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

shpack_view_error view_error_of(const Conversion& conversion) {
  shpack_view_error out{};
  if (const std::optional<ViewError>& e = conversion.view_error) {
    out.max_pct = e->max_pct;
    out.rms_pct = e->rms_pct;
    out.bound_pct = e->bound_pct;
    out.directions = static_cast<uint32_t>(kViewErrorDirections);
  }
  return out;
}

}  // namespace shpack::c_api
