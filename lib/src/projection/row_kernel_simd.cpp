#include "projection/row_kernel_simd.h"

#include <algorithm>
#include <cfloat>
#include <cstring>

#include "projection/texel_policy.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SHPACK_HAVE_AVX2_KERNELS 1
#include <immintrin.h>
#endif

namespace shpack::detail {

#if SHPACK_HAVE_AVX2_KERNELS
namespace {

#define SHPACK_AVX2 __attribute__((target("avx2")))

SHPACK_AVX2 ColumnSums plane_sums_avx2(const float* v, const ColumnTables& t,
                                       std::uint32_t width) noexcept {
  // Lanes 0-3 in the first register of each pair, lanes 4-7 in the second.
  __m256d acc[5][2];
  for (auto& pair : acc) pair[0] = pair[1] = _mm256_setzero_pd();
  const double* tables[4] = {t.cos1.data(), t.sin1.data(), t.cos2.data(), t.sin2.data()};
  std::uint32_t i = 0;
  for (; i + kSumLanes <= width; i += kSumLanes) {
    for (int h = 0; h < 2; ++h) {
      const __m256d x = _mm256_cvtps_pd(_mm_loadu_ps(v + i + 4 * h));
      acc[0][h] = _mm256_add_pd(acc[0][h], x);
      for (int f = 0; f < 4; ++f)
        acc[f + 1][h] = _mm256_add_pd(acc[f + 1][h], _mm256_mul_pd(x, _mm256_loadu_pd(tables[f] + i + 4 * h)));
    }
  }
  double lanes[5][kSumLanes];
  for (int f = 0; f < 5; ++f) {
    _mm256_storeu_pd(lanes[f], acc[f][0]);
    _mm256_storeu_pd(lanes[f] + 4, acc[f][1]);
  }
  for (std::uint32_t k = 0; i < width; ++i, ++k) {  // tail: lane k = i mod 8, as portable
    const double x = v[i];
    lanes[0][k] += x;
    for (int f = 0; f < 4; ++f) lanes[f + 1][k] += x * tables[f][i];
  }
  return {lane_total(lanes[0]), lane_total(lanes[1]), lane_total(lanes[2]), lane_total(lanes[3]),
          lane_total(lanes[4])};
}

// Four RGB texels (12 floats in three registers a, b, c) to planes:
//   a = r0 g0 b0 r1 | b = g1 b1 r2 g2 | c = b2 r3 g3 b3
//   r = a0 a3 b2 c1,  g = a1 b0 b3 c2,  b = a2 b1 c0 c3
SHPACK_AVX2 inline void deinterleave_rgb4(__m128 a, __m128 b, __m128 c, __m128& r, __m128& g,
                                         __m128& bl) noexcept {
  const __m128 r_hi = _mm_shuffle_ps(b, c, _MM_SHUFFLE(1, 1, 2, 2));          // b2 b2 c1 c1
  r = _mm_shuffle_ps(a, r_hi, _MM_SHUFFLE(2, 0, 3, 0));                       // a0 a3 b2 c1
  const __m128 g_lo = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 1, 1));          // a1 a1 b0 b0
  const __m128 g_hi = _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 2, 3, 3));          // b3 b3 c2 c2
  g = _mm_shuffle_ps(g_lo, g_hi, _MM_SHUFFLE(2, 0, 2, 0));                    // a1 b0 b3 c2
  const __m128 b_lo = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 1, 2, 2));          // a2 a2 b1 b1
  const __m128 b_hi = _mm_shuffle_ps(c, c, _MM_SHUFFLE(3, 3, 0, 0));          // c0 c0 c3 c3
  bl = _mm_shuffle_ps(b_lo, b_hi, _MM_SHUFFLE(2, 0, 2, 0));                   // a2 b1 c0 c3
}

// Lanes whose value needs no policy: finite and >= 0 (ordered compares are false for NaN).
SHPACK_AVX2 inline __m128 clean4(__m128 v) noexcept {
  return _mm_and_ps(_mm_cmpge_ps(v, _mm_setzero_ps()), _mm_cmple_ps(v, _mm_set1_ps(FLT_MAX)));
}

// The policies (texel_policy.h) on four values of one channel: NaN and +-Inf (unordered,
// or |v| > FLT_MAX) to 0, then values below 0 to 0 under clamp; the lanes so marked are
// or-ed into `nonfinite` and `negative`.
SHPACK_AVX2 inline __m128 apply_policy4(__m128 v, bool clamp_negative, __m128& nonfinite,
                                        __m128& negative) noexcept {
  const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), v);
  const __m128 bad = _mm_cmp_ps(magnitude, _mm_set1_ps(FLT_MAX), _CMP_NLE_UQ);
  v = _mm_andnot_ps(bad, v);
  const __m128 below = _mm_cmp_ps(v, _mm_setzero_ps(), _CMP_LT_OQ);  // false for -0
  if (clamp_negative) v = _mm_andnot_ps(below, v);
  nonfinite = _mm_or_ps(nonfinite, bad);
  negative = _mm_or_ps(negative, below);
  return v;
}

// Four texels (columns x..x+3 of row y) through the policies, counted.
SHPACK_AVX2 inline void apply_policies4(__m128& r, __m128& g, __m128& b, std::uint32_t x, std::uint32_t y,
                                        bool clamp_negative, TexelCounts& counts) noexcept {
  __m128 nonfinite = _mm_setzero_ps(), negative = nonfinite;
  r = apply_policy4(r, clamp_negative, nonfinite, negative);
  g = apply_policy4(g, clamp_negative, nonfinite, negative);
  b = apply_policy4(b, clamp_negative, nonfinite, negative);
  count_texels(static_cast<std::uint32_t>(_mm_movemask_ps(nonfinite)),
               static_cast<std::uint32_t>(_mm_movemask_ps(negative)), x, y, counts);
}

SHPACK_AVX2 bool load_rgb_f32_avx2(const ImageView& row, std::uint32_t y, bool clamp_negative,
                                   std::span<float> scratch, TexelCounts& counts) noexcept {
  const std::uint32_t width = row.width;
  const std::int64_t stride = row.pixel_stride;
  if (stride != 12 && stride != 16) return false;  // other layouts take the portable loader
  float* r_out = scratch.data();
  float* g_out = r_out + width;
  float* b_out = g_out + width;
  const float* p = reinterpret_cast<const float*>(row.data);
  __m128 vmax = _mm_setzero_ps();
  // RGBA-strided groups read the last texel's 4th float, which a padded RGB view need not
  // have: the last texel is always left to the scalar tail.
  const std::uint32_t over = stride == 16 ? 1 : 0;
  std::uint32_t x = 0;
  for (; x + 4 + over <= width; x += 4) {
    __m128 r, g, b;
    if (stride == 12) {
      const float* q = p + 3 * x;
      deinterleave_rgb4(_mm_loadu_ps(q), _mm_loadu_ps(q + 4), _mm_loadu_ps(q + 8), r, g, b);
    } else {
      const float* q = p + 4 * x;
      __m128 t0 = _mm_loadu_ps(q), t1 = _mm_loadu_ps(q + 4), t2 = _mm_loadu_ps(q + 8),
             t3 = _mm_loadu_ps(q + 12);
      _MM_TRANSPOSE4_PS(t0, t1, t2, t3);
      r = t0, g = t1, b = t2;
    }
    // The check costs what a clean row always paid; only a group holding a NaN, an Inf
    // or a negative value takes the policies, in place, at the same position.
    if (_mm_movemask_ps(_mm_and_ps(clean4(r), _mm_and_ps(clean4(g), clean4(b)))) != 0xf)
      apply_policies4(r, g, b, x, y, clamp_negative, counts);
    vmax = _mm_max_ps(vmax, _mm_max_ps(r, _mm_max_ps(g, b)));
    _mm_storeu_ps(r_out + x, r);
    _mm_storeu_ps(g_out + x, g);
    _mm_storeu_ps(b_out + x, b);
  }
  float row_max = 0.0f;
  for (; x < width; ++x) {
    const float* q = p + (stride / 4) * x;
    float rgb[3] = {q[0], q[1], q[2]};
    apply_texel_policy(rgb, x, y, clamp_negative, row_max, counts);
    r_out[x] = rgb[0], g_out[x] = rgb[1], b_out[x] = rgb[2];
  }
  float lanes[4];
  _mm_storeu_ps(lanes, vmax);
  row_max = std::max({lanes[0], lanes[1], lanes[2], lanes[3], row_max});
  counts.max_value = std::max(counts.max_value, static_cast<double>(row_max));
  return true;
}

#define SHPACK_AVX512 __attribute__((target("avx512f,avx512vl")))

// GCC 12's AVX-512 cast intrinsics start from _mm256_undefined_*(), which it then flags as
// maybe-uninitialized (GCC bug 105593); the bits in question are never used.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

// Indices that pick channel c of texels 0..7 from 32 interleaved floats (lo = floats
// 0-15, hi = 16-31, as _mm512_permutex2var_ps numbers them): float k * step + c.
SHPACK_AVX512 inline __m512i channel_indices(int step, int c) noexcept {
  return _mm512_set_epi32(0, 0, 0, 0, 0, 0, 0, 0, 7 * step + c, 6 * step + c, 5 * step + c,
                          4 * step + c, 3 * step + c, 2 * step + c, step + c, c);
}

// The 5 column-sum accumulators of one channel, 8 lanes each.
struct ChannelAcc512 {
  __m512d s0, sc, ss, sc2, ss2;
};

// Lanes of `clean` whose value also needs no policy: as unsigned bits, a float is finite
// and >= +0 exactly when it is <= FLT_MAX's bits (-0 fails: the policies leave it as is).
SHPACK_AVX512 inline __mmask8 clean8(__m256 v, __mmask8 clean) noexcept {
  return _mm256_mask_cmp_epu32_mask(clean, _mm256_castps_si256(v), _mm256_set1_epi32(0x7f7fffff), _MM_CMPINT_LE);
}

// The policies on eight values of one channel, as apply_policy4, marking lanes in masks.
SHPACK_AVX512 inline __m256 apply_policy8(__m256 v, bool clamp_negative, __mmask8& nonfinite,
                                          __mmask8& negative) noexcept {
  const __m256 magnitude = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), v);
  const __mmask8 bad = _mm256_cmp_ps_mask(magnitude, _mm256_set1_ps(FLT_MAX), _CMP_NLE_UQ);
  v = _mm256_maskz_mov_ps(static_cast<__mmask8>(~bad), v);
  const __mmask8 below = _mm256_cmp_ps_mask(v, _mm256_setzero_ps(), _CMP_LT_OQ);  // false for -0
  if (clamp_negative) v = _mm256_maskz_mov_ps(static_cast<__mmask8>(~below), v);
  nonfinite = static_cast<__mmask8>(nonfinite | bad);
  negative = static_cast<__mmask8>(negative | below);
  return v;
}

// Eight texels (columns x..x+7 of row y) through the policies, counted.
SHPACK_AVX512 inline void apply_policies8(__m256& r, __m256& g, __m256& b, std::uint32_t x, std::uint32_t y,
                                          bool clamp_negative, TexelCounts& counts) noexcept {
  __mmask8 nonfinite = 0, negative = 0;
  r = apply_policy8(r, clamp_negative, nonfinite, negative);
  g = apply_policy8(g, clamp_negative, nonfinite, negative);
  b = apply_policy8(b, clamp_negative, nonfinite, negative);
  count_texels(nonfinite, negative, x, y, counts);
}

SHPACK_AVX512 inline void accumulate_channel(__m256 v, const __m512d (&tab)[4], ChannelAcc512& a,
                                             __m256& vmax) noexcept {
  vmax = _mm256_max_ps(vmax, v);
  const __m512d x = _mm512_cvtps_pd(v);
  a.s0 = _mm512_add_pd(a.s0, x);
  a.sc = _mm512_add_pd(a.sc, _mm512_mul_pd(x, tab[0]));
  a.ss = _mm512_add_pd(a.ss, _mm512_mul_pd(x, tab[1]));
  a.sc2 = _mm512_add_pd(a.sc2, _mm512_mul_pd(x, tab[2]));
  a.ss2 = _mm512_add_pd(a.ss2, _mm512_mul_pd(x, tab[3]));
}

// One pass over an interleaved float RGB (kStep = 3) or RGBA (kStep = 4) row of image row
// `y`: the 15 accumulators, the 4 tables and the 3 channels fit the 32 zmm registers
// together. Each group of 8 texels goes through the policies before it is summed.
template <int kStep>
SHPACK_AVX512 void sum_rows_avx512(const float* p, std::uint32_t width, std::uint32_t y, bool clamp_negative,
                                   const ColumnTables& t, ColumnSums (&sums)[3], TexelCounts& counts) noexcept {
  const double *cos1 = t.cos1.data(), *sin1 = t.sin1.data(), *cos2 = t.cos2.data(), *sin2 = t.sin2.data();
  __m256 vmax = _mm256_setzero_ps();
  const __m512d z = _mm512_setzero_pd();
  ChannelAcc512 r{z, z, z, z, z}, g = r, b = r;
  const __m512i pick_r = channel_indices(kStep, 0), pick_g = channel_indices(kStep, 1),
                pick_b = channel_indices(kStep, 2);
  // RGBA groups read the last texel's 4th float, which a padded RGB view need not have:
  // the last texel is then left to the scalar tail.
  constexpr std::uint32_t kOver = kStep == 4 ? 1 : 0;
  std::uint32_t i = 0;
  for (; i + kSumLanes + kOver <= width; i += kSumLanes) {
    const float* q = p + std::size_t{i} * kStep;
    const __m512 lo = _mm512_loadu_ps(q);
    const __m512 hi = kStep == 3 ? _mm512_maskz_loadu_ps(0x00ff, q + 16) : _mm512_loadu_ps(q + 16);
    const __m512d tab[4] = {_mm512_loadu_pd(cos1 + i), _mm512_loadu_pd(sin1 + i),
                            _mm512_loadu_pd(cos2 + i), _mm512_loadu_pd(sin2 + i)};
    __m256 vr = _mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_r, hi));
    __m256 vg = _mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_g, hi));
    __m256 vb = _mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_b, hi));
    // Three compares, as a clean row always paid; only a group holding a NaN, an Inf or a
    // negative value takes the policies, in place, at the same position.
    if (clean8(vb, clean8(vg, clean8(vr, 0xff))) != 0xff) apply_policies8(vr, vg, vb, i, y, clamp_negative, counts);
    accumulate_channel(vr, tab, r, vmax);
    accumulate_channel(vg, tab, g, vmax);
    accumulate_channel(vb, tab, b, vmax);
  }
  double lanes[3][5][kSumLanes];
  const ChannelAcc512* acc[3] = {&r, &g, &b};
  for (int c = 0; c < 3; ++c) {
    _mm512_storeu_pd(lanes[c][0], acc[c]->s0);
    _mm512_storeu_pd(lanes[c][1], acc[c]->sc);
    _mm512_storeu_pd(lanes[c][2], acc[c]->ss);
    _mm512_storeu_pd(lanes[c][3], acc[c]->sc2);
    _mm512_storeu_pd(lanes[c][4], acc[c]->ss2);
  }
  float lane_max[8];
  _mm256_storeu_ps(lane_max, vmax);
  float row_max = 0.0f;
  for (float m : lane_max) row_max = std::max(row_max, m);
  const double* tables[4] = {cos1, sin1, cos2, sin2};
  for (std::uint32_t k = 0; i < width; ++i, ++k) {  // tail: lane k = i mod 8, as portable
    const float* q = p + std::size_t{i} * kStep;
    float rgb[3] = {q[0], q[1], q[2]};
    apply_texel_policy(rgb, i, y, clamp_negative, row_max, counts);
    for (int c = 0; c < 3; ++c) {
      const double x = rgb[c];
      lanes[c][0][k] += x;
      for (int f = 0; f < 4; ++f) lanes[c][f + 1][k] += x * tables[f][i];
    }
  }
  for (int c = 0; c < 3; ++c)
    sums[c] = {lane_total(lanes[c][0]), lane_total(lanes[c][1]), lane_total(lanes[c][2]),
               lane_total(lanes[c][3]), lane_total(lanes[c][4])};
  counts.max_value = std::max(counts.max_value, static_cast<double>(row_max));
}

SHPACK_AVX512 bool sum_rgb_f32_avx512(const ImageView& row, std::uint32_t y, bool clamp_negative,
                                      const ColumnTables& t, ColumnSums (&sums)[3],
                                      TexelCounts& counts) noexcept {
  const float* p = reinterpret_cast<const float*>(row.data);
  if (row.pixel_stride == 12) {
    sum_rows_avx512<3>(p, row.width, y, clamp_negative, t, sums, counts);
  } else if (row.pixel_stride == 16) {
    sum_rows_avx512<4>(p, row.width, y, clamp_negative, t, sums, counts);
  } else {
    return false;  // other layouts take the portable loader
  }
  return true;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

SimdKernels detect() noexcept {
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl"))
    return {plane_sums_avx2, load_rgb_f32_avx2, sum_rgb_f32_avx512};
  if (__builtin_cpu_supports("avx2")) return {plane_sums_avx2, load_rgb_f32_avx2, nullptr};
  return {plane_sums_portable, nullptr, nullptr};
}

}  // namespace

const SimdKernels& simd_kernels() noexcept {
  static const SimdKernels kernels = detect();
  return kernels;
}

#else

const SimdKernels& simd_kernels() noexcept {
  static const SimdKernels kernels = {plane_sums_portable, nullptr, nullptr};
  return kernels;
}

#endif

}  // namespace shpack::detail
