#include "shpack/study/load_average.h"

#include <charconv>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace shpack::study {

std::array<double, 3> parse_load_average(std::string_view text) {
  std::array<double, 3> load;
  load.fill(std::numeric_limits<double>::quiet_NaN());
  const char* p = text.data();
  const char* const end = text.data() + text.size();
  for (double& value : load) {
    while (p != end && *p == ' ') ++p;
    const auto [next, ec] = std::from_chars(p, end, value);
    if (ec != std::errc()) break;
    p = next;
  }
  return load;
}

std::array<double, 3> read_load_average() {
  std::ifstream in("/proc/loadavg");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_load_average(text);
}

}  // namespace shpack::study
