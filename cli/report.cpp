#include "report.h"

#include <iostream>

namespace shpack::cli {

void report_error(std::string_view line) { std::cerr << "shpack: " << line << '\n'; }

void report_usage_error(std::string_view command, std::string_view line) {
  std::cerr << "shpack: " << line << " (see shpack " << command << (command.empty() ? "" : " ") << "--help)\n";
}

}  // namespace shpack::cli
