// c_api_common.h - what the C ABI's entry points share (shpack_c.h): the translation of the
// core's Status into a return code and shpack_error, of a shpack_image into an ImageView, and
// of a Conversion into a shpack_result. Internal to the shared library.
#pragma once

#include "shpack/pipeline.h"
#include "shpack/shpack_c.h"

namespace shpack::c_api {

// The return code of `st`, also written to `error` when it is not NULL.
int32_t report(const Status& st, shpack_error* error);

// report() of an InvalidArgument with the static message `what`.
int32_t invalid(const char* what, shpack_error* error);

// The core's view of a shpack_image (0 strides mean packed), resolved (resolve_view).
Status to_view(const shpack_image& image, ImageView& view);

// The value policies of `convert` (--nonfinite, --negative) from SHPACK_NONFINITE_* and
// SHPACK_NEGATIVE_* into `out`; InvalidArgument for any other value.
Status to_policies(int32_t nonfinite, int32_t negative, ConvertOptions& out);

// The SH record of a conversion.
shpack_result result_of(const Conversion& conversion);

// Its view error (view_error.h); zeros when it has none.
shpack_view_error view_error_of(const Conversion& conversion);

}  // namespace shpack::c_api
