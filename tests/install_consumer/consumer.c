/* Uses the installed C ABI from C: the uniform environment of consumer.cpp through
 * shpack_convert_equirect and shpack_convert, ShadeSH9 on its shader vectors, and an error
 * report. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shpack/shpack_c.h"

int main(void) {
  const float texel[3] = {0.5f, 1.0f, 2.0f};
  shpack_image image = {texel, SHPACK_PIXEL_F32, 1, 1, 3, 0, 0};
  shpack_options options;
  shpack_result result;
  shpack_error error;
  float rgb[3];
  int c;
  if (shpack_abi_version() != SHPACK_C_ABI_VERSION) {
    fprintf(stderr, "consumer_c: ABI %d, header %d\n", (int)shpack_abi_version(), SHPACK_C_ABI_VERSION);
    return 1;
  }
  shpack_default_options(&options);
  if (shpack_convert_equirect(&image, &options, &result, &error) != SHPACK_OK) {
    fprintf(stderr, "consumer_c: %s: %s\n", shpack_status_name(error.code), error.message);
    return 1;
  }
  shpack_shade_sh9(result.shader, 0.0f, 1.0f, 0.0f, rgb);
  for (c = 0; c < 3; ++c) {
    if (fabs(result.unity_sh[9 * c] - texel[c]) > 1e-6 * texel[c] || fabs(rgb[c] - texel[c]) > 1e-6 * texel[c]) {
      fprintf(stderr, "consumer_c: channel %d: sh %.9g, ShadeSH9 %.9g, want %.9g\n", c, result.unity_sh[9 * c],
              rgb[c], texel[c]);
      return 1;
    }
  }
  { /* The same texel as a 1 x 1 cross, a uniform environment in any layout, via shpack_convert. */
    shpack_map map;
    shpack_convert_options convert;
    shpack_conversion out;
    memset(&map, 0, sizeof map);
    map.struct_size = sizeof map;
    map.layout = SHPACK_LAYOUT_HCROSS;
    map.image = image;
    shpack_default_convert_options(&convert);
    out.struct_size = sizeof out;
    if (shpack_convert(&map, &convert, &out, &error) != SHPACK_OK ||
        fabs(out.sh.unity_sh[0] - texel[0]) > 1e-6 * texel[0] || out.has_sun != 0) {
      fprintf(stderr, "consumer_c: shpack_convert of a 1 x 1 cross: %s\n", error.message);
      return 1;
    }
  }
  image.width = 0; /* an error comes back as a code and a static message */
  if (shpack_convert_equirect(&image, &options, &result, &error) != SHPACK_BAD_VIEW || error.code != SHPACK_BAD_VIEW ||
      strlen(error.message) == 0) {
    fprintf(stderr, "consumer_c: a 0-wide image was not reported as bad_view\n");
    return 1;
  }
  printf("consumer_c: ok (shpack %s)\n", shpack_version());
  return 0;
}
