/* shpack_c.h - the C ABI of shpack: Unity L2 spherical harmonics from pixels in memory.
 *
 * For Unity native plugins (P/Invoke), other languages and other build systems: plain C
 * types, fixed-size arrays, caller-owned memory, an opaque handle for streaming, and an
 * error code plus a message on every fallible call. Nothing throws across this boundary and
 * nothing here keeps hidden error state: a message is a static string, valid forever.
 *
 * What it computes is what `shpack convert` computes for a map held in memory (docs/json-format.md,
 * docs/conventions.md, docs/layouts.md): radiance coefficients in Unity's frame, the 27 floats
 * of a UnityEngine.Rendering.SphericalHarmonicsL2, the seven shader vectors
 * unity_SHAr..unity_SHC, the minimum of E/pi per channel, the extracted sun or lights and the
 * error of what Unity shows against the exact E/pi of the map (its view error),
 * bit-identical to the CLI's JSON for the same texels and options (pipeline.h).
 * shpack_convert takes every layout and option of `convert`; shpack_convert_equirect and the
 * projector are the first version's equirect-only calls, kept as they were.
 *
 * Layout of the arrays, all channel-major (R, G, B):
 *   radiance_sh[9 c + i]   L_c,i, doubles
 *   unity_sh[9 c + i]      SphericalHarmonicsL2 sh[c, i], floats
 *   shader[4 v + k]        v = 0..6: unity_SHAr, SHAg, SHAb, SHBr, SHBg, SHBb, SHC; k = x, y, z, w
 *
 * Structs have a fixed layout on every 64-bit platform (no padding between members as
 * declared; shpack_result has 4 bytes of tail padding), so C# can mirror them with
 * LayoutKind.Sequential. The structs of shpack_convert start with struct_size, which the
 * caller sets to the sizeof it was compiled with: a later version that appends members can
 * tell an older caller's struct by its size. Thread safety: every function
 * may be called from any thread; one projector must not be used by two threads at once.
 */
#ifndef SHPACK_C_H
#define SHPACK_C_H

#include <stdint.h>

#if defined(_WIN32)
#if defined(SHPACK_C_BUILDING)
#define SHPACK_C_API __declspec(dllexport)
#else
#define SHPACK_C_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define SHPACK_C_API __attribute__((visibility("default")))
#else
#define SHPACK_C_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Raised when a function, struct or meaning changes incompatibly. */
#define SHPACK_C_ABI_VERSION 1

/* Return codes (int32_t). */
enum {
  SHPACK_OK = 0,
  SHPACK_INVALID_ARGUMENT = 1, /* an option, pointer or size out of its domain (see message) */
  SHPACK_BAD_VIEW = 2,         /* the image description is malformed (strides, sizes, null data) */
  SHPACK_NONFINITE_TEXEL = 3,  /* NaN/Inf texel under SHPACK_NONFINITE_ERROR; error.x, .y locate the first */
  SHPACK_BAD_SEQUENCE = 4,     /* a projector call out of order (rows not contiguous, finished twice) */
  SHPACK_OUT_OF_MEMORY = 5,    /* a buffer or a worker thread could not be created */
  SHPACK_OUT_OF_RANGE = 6,     /* the lighting is too bright for Unity's float32 coefficients */
  SHPACK_INTERNAL = 99         /* an error of the core this ABI version does not name */
};

/* Texel types of shpack_image. */
enum { SHPACK_PIXEL_F32 = 0, SHPACK_PIXEL_F16 = 1 };
/* shpack_options.method: exact integrals per texel, or the basis at texel centres. */
enum { SHPACK_METHOD_EXACT = 0, SHPACK_METHOD_CENTER = 1 };
/* shpack_options.nonfinite: fail on NaN/Inf texels, or count them as 0. */
enum { SHPACK_NONFINITE_ERROR = 0, SHPACK_NONFINITE_ZERO = 1 };
/* shpack_options.negative: keep negative texels, or count them as 0. */
enum { SHPACK_NEGATIVE_KEEP = 0, SHPACK_NEGATIVE_CLAMP = 1 };

typedef struct shpack_error {
  int32_t code;        /* SHPACK_OK or an error code */
  uint32_t x, y, face; /* the texel, for SHPACK_NONFINITE_TEXEL */
  const char* message; /* static, never freed: "ok" or what went wrong */
} shpack_error;

/* A view of pixels the caller owns: an equirect (latitude-longitude) image as Unity's
 * Skybox/Panoramic maps it, or a band of its rows (shpack_projector_add_rows). Values are
 * linear radiance. channels: 1 = grey, 2 = grey + alpha, 3 = RGB, 4+ = RGB + ignored. */
typedef struct shpack_image {
  const void* data;
  int32_t pixel_type;     /* SHPACK_PIXEL_F32 or SHPACK_PIXEL_F16 */
  uint32_t width, height, channels;
  int64_t pixel_stride;   /* bytes between pixels of a row; 0: packed */
  int64_t row_stride;     /* bytes between rows, may be negative (bottom-up images); 0: packed */
} shpack_image;

typedef struct shpack_options {
  int32_t method;      /* SHPACK_METHOD_* */
  int32_t nonfinite;   /* SHPACK_NONFINITE_* */
  int32_t negative;    /* SHPACK_NEGATIVE_* */
  uint32_t threads;    /* worker threads, 0 = all cores; the result does not depend on it */
  double intensity;    /* linear factor on the radiance, finite and >= 0 */
  double rotate_deg;   /* yaw about +Y, the sense and number of Skybox/Panoramic's _Rotation */
  const char* window;  /* "none", "hanning:W", "lanczos:W", "unity", "sloan", "optimal"; NULL = "none" */
} shpack_options;

typedef struct shpack_result {
  double radiance_sh[27];    /* L_c,i with intensity, rotation and window applied */
  double min_e_over_pi[3];   /* exact minimum over the sphere of E/pi, per channel */
  double min_direction[9];   /* where it is attained, (x, y, z) per channel, Unity's frame */
  double window_factors[9];  /* per channel, the factors applied to bands 0, 1, 2; NaN for "optimal" (none) */
  uint64_t nonfinite_texels; /* texels with a NaN/Inf channel (counted as 0 under ZERO) */
  uint64_t negative_texels;  /* texels with a negative channel */
  float unity_sh[27];        /* SphericalHarmonicsL2 sh[c, i] */
  float shader[28];          /* unity_SHAr .. unity_SHC */
} shpack_result;

/* ---- shpack_convert: every layout and option of `shpack convert` ----------------------- */

/* shpack_map.layout (docs/layouts.md). AUTO detects it from the image's size as `convert`
 * does: 2:1 equirect, 4:3 HCROSS, 3:4 VCROSS, 6:1 HSTRIP, 1:6 VSTRIP; a square image is
 * ambiguous and must be named. FACES: the six faces[] instead of one image. */
enum {
  SHPACK_LAYOUT_AUTO = 0,
  SHPACK_LAYOUT_EQUIRECT = 1,   /* Unity's Skybox/Panoramic latitude-longitude */
  SHPACK_LAYOUT_HCROSS = 2,     /* 4N x 3N */
  SHPACK_LAYOUT_VCROSS = 3,     /* 3N x 4N, -Z rotated 180 degrees */
  SHPACK_LAYOUT_HSTRIP = 4,     /* 6N x N, +X -X +Y -Y +Z -Z left to right */
  SHPACK_LAYOUT_VSTRIP = 5,     /* N x 6N, the same top to bottom */
  SHPACK_LAYOUT_OCTAHEDRAL = 6, /* Unity's octahedral encoding, N x N */
  SHPACK_LAYOUT_ANGULAR = 7,    /* Debevec's angular map, N x N */
  SHPACK_LAYOUT_MIRRORBALL = 8, /* a mirror ball photographed along +Z, N x N */
  SHPACK_LAYOUT_FACES = 9       /* six N x N faces in Unity's CubemapFace order */
};
/* shpack_map.cube_frame: the world cube faces were made in (`convert --cube-frame`). */
enum { SHPACK_CUBE_FRAME_UNITY = 0, SHPACK_CUBE_FRAME_GL = 1, SHPACK_CUBE_FRAME_THREEJS = 2 };

/* The pixels of one environment map. Each face of FACES is a view like `image`, row 0 at
 * the top of the face as docs/conventions.md orients it (Unity's CubemapFace order +X, -X,
 * +Y, -Y, +Z, -Z); a bottom-up face takes a negative row_stride. */
typedef struct shpack_map {
  uint32_t struct_size; /* sizeof(shpack_map) */
  int32_t layout;       /* SHPACK_LAYOUT_* */
  int32_t cube_frame;   /* SHPACK_CUBE_FRAME_*; UNITY for layouts that are not cubes */
  uint32_t reserved;    /* 0; keeps `image` 8-byte aligned without hidden padding */
  shpack_image image;   /* every layout but FACES */
  shpack_image faces[6];
} shpack_map;

typedef struct shpack_convert_options {
  uint32_t struct_size; /* sizeof(shpack_convert_options) */
  int32_t nonfinite;    /* SHPACK_NONFINITE_* */
  int32_t negative;     /* SHPACK_NEGATIVE_* */
  uint32_t threads;     /* worker threads, 0 = all cores; the result does not depend on it */
  double intensity;     /* linear factor on the radiance, finite and >= 0 (`--intensity`) */
  double exposure_ev;   /* the radiance is scaled by intensity * 2^exposure_ev (`--exposure`) */
  double rotate_deg;    /* yaw about +Y, as Skybox/Panoramic's _Rotation (`--rotate`) */
  const char* method;   /* as `--method`: "exact", "center", "mip:K", "mc:N[:SEED]", ...; NULL = "exact" */
  const char* window;   /* as `--window`; NULL = "none" */
  int32_t extract_sun;  /* 1: take the sun out of an equirect map as a light (`--extract-sun`) */
  int32_t l1;           /* 1: band 2 removed, for Light Probe Proxy Volumes (`--l1`) */
  /* Appended after the first release (a caller whose struct_size ends before them gets 0s): */
  uint32_t extract_lights; /* 0..8: up to this many lights taken out (`--extract-lights`); 0 with extract_sun */
  uint32_t reserved;       /* 0 */
} shpack_convert_options;

/* A light taken out of the map, in the output's frame and colours (the JSON's "sun"). */
typedef struct shpack_light {
  double direction[3];  /* unit, towards the light, Unity's frame, rotation applied */
  double irradiance[3]; /* E per channel at normal incidence, intensity applied (fitted for extract_lights) */
  double sky_level[3];  /* the radiance its texels were given (extract_lights: the level around
                           its source, whose texels are left as they are) */
  double angular_radius_deg, solid_angle_sr;
  uint64_t texels;      /* how many texels were replaced */
  /* As a Unity directional light (unity_light in the JSON): */
  double forward[3];    /* = -direction, the light's +Z */
  double euler_deg[3];  /* Transform.eulerAngles: pitch, yaw, 0 */
  double quaternion[4]; /* x, y, z, w: turns +Z into forward */
  double color[3];      /* linear, largest channel 1 */
  double color_srgb[3]; /* the same colour sRGB-encoded, for Light.color */
  double intensity;     /* color * intensity = irradiance / pi */
} shpack_light;

/* What Unity shows against the exact E/pi of the input, in percent of its mean E/pi
 * (docs/json-format.md, diagnostics.unity_view_error_*): the packed shader vectors plus every
 * extracted light, at `directions` spherical Fibonacci normals (rms_pct), the max also searched
 * for between them (view_error.h). */
typedef struct shpack_view_error {
  double max_pct, rms_pct, bound_pct; /* each error is within bound_pct of the exact one */
  uint32_t directions, reserved;
} shpack_view_error;

/* A light of extract_lights, with the max error of what Unity shows with the lights chosen
 * before it and with it too (error_after_pct < error_before_pct), at the view directions the
 * lights are fitted at. */
typedef struct shpack_extracted_light {
  shpack_light light;
  double error_before_pct, error_after_pct;
} shpack_extracted_light;

#define SHPACK_MAX_EXTRACTED_LIGHTS 8

typedef struct shpack_conversion {
  uint32_t struct_size; /* set by the caller: sizeof(shpack_conversion) */
  int32_t has_sun;      /* 1 when extract_sun found a sun: `sun` holds it (else zeros) */
  shpack_result sh;
  shpack_light sun;
  /* Appended after the first release (not written for a caller whose struct_size ends before them): */
  shpack_view_error view_error;
  double window_rms_change[3]; /* per channel: the RMS change of E/pi the window made, over the RMS before it */
  int32_t window_planes[3];    /* "optimal": per channel, the directions its cutting planes needed */
  int32_t window_impossible;   /* bit c set: channel c rings with a negative mean, left as it was */
  uint32_t light_count;      /* lights[0 .. light_count - 1] hold the lights extracted, in the order chosen */
  uint32_t light_candidates; /* how many candidates they were chosen from */
  shpack_extracted_light lights[SHPACK_MAX_EXTRACTED_LIGHTS];
} shpack_conversion;

/* The library's ABI version (SHPACK_C_ABI_VERSION when it was built) and version text. */
SHPACK_C_API int32_t shpack_abi_version(void);
SHPACK_C_API const char* shpack_version(void);

/* A short stable name of a return code ("ok", "invalid_argument", ...). */
SHPACK_C_API const char* shpack_status_name(int32_t code);

/* exact, error, keep, all cores, intensity 1, no rotation, no window. */
SHPACK_C_API void shpack_default_options(shpack_options* options);

/* Projects a whole equirect image and finishes it as `shpack convert` does. `error` may be
 * NULL. On failure `result` is left as it was. */
SHPACK_C_API int32_t shpack_convert_equirect(const shpack_image* image, const shpack_options* options,
                                             shpack_result* result, shpack_error* error);

/* exact, error, keep, all cores, intensity 1, exposure 0, no rotation, no window, no sun, L2;
 * struct_size set. */
SHPACK_C_API void shpack_default_convert_options(shpack_convert_options* options);

/* Converts a map of any layout as `shpack convert` does, through the same pipeline: stages 2
 * to 4 of pipeline.h. Sampling methods and extract_sun take equirect maps only, and
 * octahedral, angular and mirror ball maps the exact method only. extract_sun works on a
 * copy: the caller's pixels are never written. The first NaN/Inf texel is reported in image
 * coordinates (face coordinates and error.face for FACES). `error` may be NULL. On failure
 * `out` is left as it was. */
SHPACK_C_API int32_t shpack_convert(const shpack_map* map, const shpack_convert_options* options,
                                    shpack_conversion* out, shpack_error* error);

/* Streaming, for images that do not fit in memory: create with the full size, add bands of
 * consecutive rows from the top (any heights), finish once, destroy. Memory is bounded by
 * the caller's band. The result equals shpack_convert_equirect's on the whole image, and
 * shpack_projector_view_error, after a successful finish, gives its view error, equal to
 * shpack_convert's. */
typedef struct shpack_projector shpack_projector;
SHPACK_C_API int32_t shpack_projector_create(uint32_t width, uint32_t height, const shpack_options* options,
                                             shpack_projector** projector, shpack_error* error);
SHPACK_C_API int32_t shpack_projector_add_rows(shpack_projector* projector, const shpack_image* rows,
                                               uint32_t first_row, shpack_error* error);
SHPACK_C_API int32_t shpack_projector_finish(shpack_projector* projector, shpack_result* result,
                                             shpack_error* error);
SHPACK_C_API int32_t shpack_projector_view_error(const shpack_projector* projector, shpack_view_error* view_error,
                                                 shpack_error* error);
SHPACK_C_API void shpack_projector_destroy(shpack_projector* projector); /* NULL is allowed */

/* Unity's ShadeSH9 (SHEvalLinearL0L1 + SHEvalLinearL2), in float, from the 28 shader floats,
 * for the normal (x, y, z) in Unity's frame: E/pi per channel into rgb[3]. */
SHPACK_C_API int32_t shpack_shade_sh9(const float shader[28], float x, float y, float z, float rgb[3]);

#ifdef __cplusplus
}
#endif

#endif /* SHPACK_C_H */
