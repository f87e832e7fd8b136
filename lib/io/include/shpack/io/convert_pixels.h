// convert_pixels.h - the pipeline (shpack/pipeline.h) run on pixels a caller holds in memory,
// to the same document a file gives (the Python module's shpack.project).
//
// Stage 1 is the caller's views, resolved as map_source.h resolves a file: the layout named
// by settings.source.layout or detected from the shape (the same refusals, naming the
// layouts that fit), the colour space named by settings.source.colorspace (Auto: Rec. 709,
// pixels in memory carry no chromaticities), the cube frame. Channels as image_view.h reads
// them: 1 or 2 (grey, then alpha) as grey, 3 or more as R, G, B then ignored ones. Stages 2
// to 5 are convert_map and make_document, the stages of a file read whole; the streamed
// stage 3 of a file computes the same numbers (tests/io/c_api_test.cpp and
// tests/python compare them bit for bit), so the document equals the file's but for
// source.files and source.sha256, which are empty: no file was read.
//
// Errors name `name` where a file's errors name the file ("array: 3 NaN/Inf texels (first
// at x=1, y=0)"; "array[2]: ..." for face 2 of six), with the IoErrc a file's would have.
// settings.source.layer must be empty (pixels have no parts); settings.source.max_texels
// is not applied (the pixels are in memory already). The caller's pixels are never written:
// a transform works on a copy (make_writable).
#pragma once

#include <array>
#include <string>

#include "shpack/document.h"
#include "shpack/image_view.h"
#include "shpack/io/convert.h"
#include "shpack/io/io_status.h"

namespace shpack::io {

// One image of any layout but faces.
IoStatus convert_pixels(const ImageView& image, const std::string& name, const ConvertSettings& settings,
                        ShDocument& out);

// Six faces in Unity's face order (+X, -X, +Y, -Y, +Z, -Z), square and of one size, as
// `convert --faces` reads six files (settings.source.layout is ignored).
IoStatus convert_pixel_faces(const std::array<ImageView, kCubeFaceCount>& faces, const std::string& name,
                             const ConvertSettings& settings, ShDocument& out);

}  // namespace shpack::io
