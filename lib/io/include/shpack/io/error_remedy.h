// error_remedy.h - the one-line error of a failed conversion, with its remedy where there is
// one: what `shpack convert` prints after "shpack: ", and what the Python module raises.
//
// The io messages state the facts ("<file>: 3 NaN/Inf texels (first at x=1, y=0)"); the
// remedy names an option ("; use --nonfinite=zero to replace them"). Naming the layout is no
// remedy when one is named already (a shape that does not fit it): the message then lists
// the layouts that would fit, which is the remedy.
#pragma once

#include <string>

#include "shpack/io/io_status.h"
#include "shpack/layout.h"

namespace shpack::io {

// st.message, and the remedy its code has; `requested` is the layout asked for (Auto when
// none was named).
std::string with_remedy(const IoStatus& st, Layout requested);

}  // namespace shpack::io
