#include "shpack/document.h"

#include <utility>

namespace shpack {

ShDocument make_document(ShSource source, ShReading reading, const ConvertOptions& options,
                         const Conversion& conversion) {
  ShDocument doc;
  doc.source = std::move(source);
  doc.reading = std::move(reading);
  doc.method = options.method;
  doc.intensity = options.finish.intensity;
  doc.rotate_deg = options.finish.rotate_deg;
  doc.window = options.finish.window;
  doc.l1 = options.finish.l1;
  doc.colour_matrix = options.finish.colour_matrix;
  doc.sun_extraction = options.extract_sun;
  doc.light_extraction = options.extract_lights;
  doc.sh = conversion.sh;
  doc.texels = {conversion.stats.nonfinite_texels, conversion.stats.negative_texels};
  doc.sun = conversion.sun;
  doc.lights = conversion.lights;
  doc.light_candidates = conversion.light_candidates;
  doc.view_error = conversion.view_error;
  return doc;
}

}  // namespace shpack
