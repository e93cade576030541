// Moments of simulated time, as `verify --at` and `render --at` take them: seconds from the
// start, to the millisecond, named t_0.500 (their stills' files are t_0.500.png).
#pragma once
#include <string>
#include <vector>

namespace impulse::demos {

// "0.5,1,2" -> {0.5, 1, 2}, each rounded to the millisecond, sorted, without repeats. Throws
// std::invalid_argument naming `option` for anything else (a negative or non-numeric item).
std::vector<double> parse_moments(const std::string& list, const std::string& option = "--at");

// The same moment, whichever way it was computed: its whole milliseconds.
long long moment_key(double seconds);

// "t_0.500", the name of a moment's still.
std::string moment_name(double seconds);

}  // namespace impulse::demos
