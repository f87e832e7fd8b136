// Uses the installed C++ core: a uniform environment of radiance R projects to sh[c][0] = R
// and zeros elsewhere (docs/conventions.md section 5). Exit code 0 when it does.
#include <cmath>
#include <cstdio>

#include "shpack/convolution.h"
#include "shpack/project.h"
#include "shpack/unity_pack.h"

int main() {
  const float texel[3] = {0.5f, 1.0f, 2.0f};  // a 1x1 map is a uniform environment
  shpack::ShL2 radiance;
  if (const shpack::Status st = shpack::project_equirect(shpack::make_view(texel, 1, 1, 3), {}, radiance); !st.ok()) {
    std::fprintf(stderr, "consumer_cpp: project_equirect: %s\n", st.what);
    return 1;
  }
  const shpack::UnitySphericalHarmonicsL2 sh = shpack::to_unity_sh(shpack::radiance_to_unity_form(radiance));
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 9; ++i) {
      const double want = i == 0 ? texel[c] : 0.0;
      if (std::fabs(sh[c][i] - want) > 1e-6 * texel[c]) {
        std::fprintf(stderr, "consumer_cpp: sh[%d][%d] = %.9g, want %.9g\n", c, i, sh[c][i], want);
        return 1;
      }
    }
  }
  std::puts("consumer_cpp: ok");
  return 0;
}
