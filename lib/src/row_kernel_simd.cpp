#include "row_kernel_simd.h"

#include <algorithm>
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
  __m256d s0 = _mm256_setzero_pd(), sc = s0, ss = s0, sc2 = s0, ss2 = s0;
  std::uint32_t i = 0;
  for (; i + kSumLanes <= width; i += kSumLanes) {
    const __m256d x = _mm256_cvtps_pd(_mm_loadu_ps(v + i));
    s0 = _mm256_add_pd(s0, x);
    sc = _mm256_add_pd(sc, _mm256_mul_pd(x, _mm256_loadu_pd(&t.cos1[i])));
    ss = _mm256_add_pd(ss, _mm256_mul_pd(x, _mm256_loadu_pd(&t.sin1[i])));
    sc2 = _mm256_add_pd(sc2, _mm256_mul_pd(x, _mm256_loadu_pd(&t.cos2[i])));
    ss2 = _mm256_add_pd(ss2, _mm256_mul_pd(x, _mm256_loadu_pd(&t.sin2[i])));
  }
  double l0[kSumLanes], lc[kSumLanes], ls[kSumLanes], lc2[kSumLanes], ls2[kSumLanes];
  _mm256_storeu_pd(l0, s0);
  _mm256_storeu_pd(lc, sc);
  _mm256_storeu_pd(ls, ss);
  _mm256_storeu_pd(lc2, sc2);
  _mm256_storeu_pd(ls2, ss2);
  for (std::uint32_t k = 0; i < width; ++i, ++k) {  // tail: lane k = i mod 4, as portable
    const double x = v[i];
    l0[k] += x;
    lc[k] += x * t.cos1[i];
    ls[k] += x * t.sin1[i];
    lc2[k] += x * t.cos2[i];
    ls2[k] += x * t.sin2[i];
  }
  return {lane_total(l0), lane_total(lc), lane_total(ls), lane_total(lc2), lane_total(ls2)};
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
  std::uint32_t x = 0;
  for (; x + 4 <= width; x += 4) {
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

SimdKernels detect() noexcept {
  if (__builtin_cpu_supports("avx2")) return {plane_sums_avx2, load_clean_rgb_f32_avx2};
  return {plane_sums_portable, nullptr};
}

}  // namespace

const SimdKernels& simd_kernels() noexcept {
  static const SimdKernels kernels = detect();
  return kernels;
}

#else

const SimdKernels& simd_kernels() noexcept {
  static const SimdKernels kernels = {plane_sums_portable, nullptr};
  return kernels;
}

#endif

}  // namespace shpack::detail
