#include "projection/row_kernel_simd.h"

#include <algorithm>
#include <cmath>
#include <cfloat>
#include <cstring>

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

SHPACK_AVX2 bool load_clean_rgb_f32_avx2(const ImageView& row, std::span<float> scratch,
                                         double& max_value) noexcept {
  const std::uint32_t width = row.width;
  const std::int64_t stride = row.pixel_stride;
  if (stride != 12 && stride != 16) return false;  // other layouts take the careful loader
  float* r_out = scratch.data();
  float* g_out = r_out + width;
  float* b_out = g_out + width;
  const float* p = reinterpret_cast<const float*>(row.data);
  const __m128 zero = _mm_setzero_ps(), top = _mm_set1_ps(FLT_MAX);
  __m128 ok = _mm_castsi128_ps(_mm_set1_epi32(-1)), vmax = zero;
  auto check = [&](__m128 v) SHPACK_AVX2 {
    // Ordered compares are false for NaN, so NaN, +-Inf and negatives all clear `ok`.
    ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpge_ps(v, zero), _mm_cmple_ps(v, top)));
    vmax = _mm_max_ps(vmax, v);
  };
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
    check(r), check(g), check(b);
    _mm_storeu_ps(r_out + x, r);
    _mm_storeu_ps(g_out + x, g);
    _mm_storeu_ps(b_out + x, b);
  }
  float tail_max = 0.0f;
  bool tail_ok = true;
  for (; x < width; ++x) {
    const float* q = p + (stride / 4) * x;
    r_out[x] = q[0], g_out[x] = q[1], b_out[x] = q[2];
    for (int c = 0; c < 3; ++c) {
      tail_ok = tail_ok && q[c] >= 0.0f && q[c] <= FLT_MAX;
      tail_max = std::max(tail_max, q[c]);
    }
  }
  if (_mm_movemask_ps(ok) != 0xf || !tail_ok) return false;
  float lanes[4];
  _mm_storeu_ps(lanes, vmax);
  const float row_max = std::max({lanes[0], lanes[1], lanes[2], lanes[3], tail_max});
  max_value = std::max(max_value, static_cast<double>(row_max));
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

SHPACK_AVX512 inline void accumulate_channel(__m256 v, const __m512d (&tab)[4], ChannelAcc512& a,
                                             __m256& vmin, __m256& vmax) noexcept {
  vmin = _mm256_min_ps(vmin, v);
  vmax = _mm256_max_ps(vmax, v);
  const __m512d x = _mm512_cvtps_pd(v);
  a.s0 = _mm512_add_pd(a.s0, x);
  a.sc = _mm512_add_pd(a.sc, _mm512_mul_pd(x, tab[0]));
  a.ss = _mm512_add_pd(a.ss, _mm512_mul_pd(x, tab[1]));
  a.sc2 = _mm512_add_pd(a.sc2, _mm512_mul_pd(x, tab[2]));
  a.ss2 = _mm512_add_pd(a.ss2, _mm512_mul_pd(x, tab[3]));
}

// One pass over an interleaved float RGB (kStep = 3) or RGBA (kStep = 4) row: the 15
// accumulators, the 4 tables and the 3 channels fit the 32 zmm registers together.
// Cleanliness needs no per-value compare: a NaN or Inf makes S0 (a plain sum, exact in
// double for any finite floats) non-finite, and a negative value pulls vmin below 0.
template <int kStep>
SHPACK_AVX512 bool sum_clean_rows_avx512(const float* p, std::uint32_t width, const ColumnTables& t,
                                         ColumnSums (&sums)[3], double& max_value) noexcept {
  const double *cos1 = t.cos1.data(), *sin1 = t.sin1.data(), *cos2 = t.cos2.data(), *sin2 = t.sin2.data();
  __m256 vmin = _mm256_setzero_ps(), vmax = vmin;
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
    accumulate_channel(_mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_r, hi)), tab, r, vmin, vmax);
    accumulate_channel(_mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_g, hi)), tab, g, vmin, vmax);
    accumulate_channel(_mm512_castps512_ps256(_mm512_permutex2var_ps(lo, pick_b, hi)), tab, b, vmin, vmax);
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
  float lane_min[8], lane_max[8];
  _mm256_storeu_ps(lane_min, vmin);
  _mm256_storeu_ps(lane_max, vmax);
  float row_max = 0.0f;
  for (int k = 0; k < 8; ++k) {
    if (!(lane_min[k] >= 0.0f)) return false;
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(lanes[c][0][k])) return false;
    row_max = std::max(row_max, lane_max[k]);
  }
  const double* tables[4] = {cos1, sin1, cos2, sin2};
  for (std::uint32_t k = 0; i < width; ++i, ++k) {  // tail: lane k = i mod 8, as portable
    for (int c = 0; c < 3; ++c) {
      const float v = p[std::size_t{i} * kStep + c];
      if (!(v >= 0.0f && v <= FLT_MAX)) return false;
      row_max = std::max(row_max, v);
      const double x = v;
      lanes[c][0][k] += x;
      for (int f = 0; f < 4; ++f) lanes[c][f + 1][k] += x * tables[f][i];
    }
  }
  for (int c = 0; c < 3; ++c)
    sums[c] = {lane_total(lanes[c][0]), lane_total(lanes[c][1]), lane_total(lanes[c][2]),
               lane_total(lanes[c][3]), lane_total(lanes[c][4])};
  max_value = std::max(max_value, static_cast<double>(row_max));
  return true;
}

SHPACK_AVX512 bool sum_clean_rgb_f32_avx512(const ImageView& row, const ColumnTables& t,
                                            ColumnSums (&sums)[3], double& max_value) noexcept {
  const float* p = reinterpret_cast<const float*>(row.data);
  if (row.pixel_stride == 12) return sum_clean_rows_avx512<3>(p, row.width, t, sums, max_value);
  if (row.pixel_stride == 16) return sum_clean_rows_avx512<4>(p, row.width, t, sums, max_value);
  return false;  // other layouts take the portable loaders
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

SimdKernels detect() noexcept {
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl"))
    return {plane_sums_avx2, load_clean_rgb_f32_avx2, sum_clean_rgb_f32_avx512};
  if (__builtin_cpu_supports("avx2")) return {plane_sums_avx2, load_clean_rgb_f32_avx2, nullptr};
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
