// report.h - exit codes and the one-line error report of the shpack command.
#pragma once

#include <string_view>

namespace shpack::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // an input or output failed
inline constexpr int kExitUsage = 2;    // the command line is wrong

// Prints "shpack: <line>" on stderr. `line` names the file and the problem.
void report_error(std::string_view line);
// A usage error: "shpack: <line> (see shpack <command> --help)", or "(see shpack --help)" for
// an empty command, so that the reader knows where the command's options are listed.
void report_usage_error(std::string_view command, std::string_view line);

}  // namespace shpack::cli
