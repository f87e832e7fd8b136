#include "convert_errors.h"

#include <string>

namespace shpack::io::detail {

IoStatus core_error(const std::filesystem::path& source, const Status& st) {
  const IoErrc code = st.code == Errc::InvalidArgument ? IoErrc::InvalidArgument
                      : st.code == Errc::OutOfRange    ? IoErrc::Unsupported
                                                       : IoErrc::Core;
  return IoStatus::error(code, source, st.what);
}

IoStatus nonfinite_error(const std::filesystem::path& source, const ProjectStats& seen, const MethodSpec& method) {
  const bool reads = !(method.method == SamplingMethod::Exact || method.method == SamplingMethod::Center);
  std::string what = std::to_string(seen.nonfinite_texels);
  if (reads) {
    what.append(" NaN/Inf texel reads by ").append(method_name(method).view());
  } else {
    what.append(" NaN/Inf texels");
  }
  what.append(" (first at x=")
      .append(std::to_string(seen.first_nonfinite_x))
      .append(", y=")
      .append(std::to_string(seen.first_nonfinite_y))
      .append(")");
  return IoStatus::error(IoErrc::NonFiniteTexel, source, what);
}

IoStatus check_settings(const std::filesystem::path& source, const ConvertSettings& settings) {
  if (Status st = check_finish_options(settings.convert.finish); !st.ok()) return core_error(source, st);
  if (Status st = validate_method(settings.convert.method); !st.ok()) return core_error(source, st);
  return IoStatus::success();
}

}  // namespace shpack::io::detail
