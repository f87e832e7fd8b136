#include "shpack/io/error_remedy.h"

namespace shpack::io {

std::string with_remedy(const IoStatus& st, Layout requested) {
  std::string line = st.message;
  switch (st.code) {
    case IoErrc::NonFiniteTexel: return line.append("; use --nonfinite=zero to replace them");
    case IoErrc::UnknownLayout:
      return requested == Layout::Auto ? line.append("; name the layout with --layout") : line;
    default: return line;
  }
}

}  // namespace shpack::io
