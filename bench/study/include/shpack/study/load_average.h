// load_average.h - how busy the machine was while `shpack bench` timed: the 1, 5 and 15
// minute load averages of /proc/loadavg (proc(5): runnable and uninterruptible tasks,
// exponentially averaged). On a machine with C cores, a load above C means the timed
// projections shared the cores and their times are inflated.
#pragma once

#include <array>
#include <string_view>

namespace shpack::study {

// The three numbers at the start of a /proc/loadavg line; NaN for each that is missing.
std::array<double, 3> parse_load_average(std::string_view text);

// parse_load_average of /proc/loadavg; NaNs where it cannot be read (not Linux).
std::array<double, 3> read_load_average();

}  // namespace shpack::study
