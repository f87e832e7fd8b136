#include "report.h"

#include <iostream>

namespace shpack::cli {

void report_error(std::string_view line) { std::cerr << "shpack: " << line << '\n'; }

}  // namespace shpack::cli
