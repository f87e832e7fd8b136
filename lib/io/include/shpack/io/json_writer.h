// json_writer.h - the output document as JSON text (docs/json-format.md).
//
// Keys appear in the order of docs/json-format.md's example. Doubles are written in the
// shortest form that reads back to the same double; each float32 of sphericalHarmonicsL2
// and shader is written as the double of equal value, so any reader gets the exact float back.
#pragma once

#include <string>

#include "shpack/document.h"

namespace shpack::io {

// The document, indented by 2, with a final line break.
std::string to_json(const ShDocument& doc);

}  // namespace shpack::io
