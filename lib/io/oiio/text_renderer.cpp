// The OpenImageIO module's text (oiio_plugin_abi.h): one line rendered by FreeType through
// ImageBufAlgo::render_text into a coverage bitmap, which shpack preview composites itself.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "oiio_plugin_abi.h"

extern "C" bool shpack_oiio_render_text(const char* utf8, const char* font, int size,
                                        std::vector<std::uint8_t>* coverage, std::uint32_t* width,
                                        std::uint32_t* height, std::string* error) {
  try {
    // The line's extent relative to its origin on the baseline; a box a size high holds the
    // ascent and the descent of any glyph of the font, with the baseline at 4/5 of it.
    const OIIO::ROI extent = OIIO::ImageBufAlgo::text_size(utf8, size, font);
    if (!extent.defined()) {
      *error = "cannot measure the text with " + std::string(font) + " (" + OIIO::geterror() + ")";
      return false;
    }
    const int w = std::max(1, extent.xend + 1), h = size, baseline = (4 * size) / 5;
    OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::zero(buf);
    const float white = 1.0f;
    if (!OIIO::ImageBufAlgo::render_text(buf, 0, baseline, utf8, size, font, OIIO::cspan<float>(&white, 1))) {
      *error = "cannot render the text (" + buf.geterror() + ")";
      return false;
    }
    coverage->resize(static_cast<std::size_t>(w) * h);
    std::vector<float> values(coverage->size());
    buf.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 1), OIIO::TypeDesc::FLOAT, values.data());
    for (std::size_t i = 0; i < values.size(); ++i)
      (*coverage)[i] = static_cast<std::uint8_t>(std::lround(255 * std::clamp(values[i], 0.0f, 1.0f)));
    *width = static_cast<std::uint32_t>(w);
    *height = static_cast<std::uint32_t>(h);
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
