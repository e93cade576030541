#include "demos/film/moments.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace impulse::demos {
namespace {

constexpr double kLatestMoment = 1e7;  // s: far past any scene (a scene is at most hours), and whole ms fit a long long

}  // namespace

std::vector<double> parse_moments(const std::string& list, const std::string& option) {
  std::vector<double> moments;
  std::stringstream stream(list + (list.empty() || list.back() == ',' ? "," : ""));  // an empty last item refused too
  std::string item;
  while (std::getline(stream, item, ',')) {
    size_t used = 0;
    double seconds = -1;
    try {
      seconds = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || !std::isfinite(seconds) || seconds < 0 || seconds > kLatestMoment)
      throw std::invalid_argument(option + " wants moments in seconds of simulated time from 0, separated by commas "
                                  "(like 0.5,1,2), got '" + list + "'");
    moments.push_back(double(moment_key(seconds)) / 1000);
  }
  if (moments.empty()) throw std::invalid_argument(option + " wants at least one moment in seconds (like 0.5,1,2)");
  std::sort(moments.begin(), moments.end());
  moments.erase(std::unique(moments.begin(), moments.end()), moments.end());
  return moments;
}

long long moment_key(double seconds) { return std::llround(seconds * 1000); }

std::string moment_name(double seconds) {
  char name[40];
  std::snprintf(name, sizeof name, "t_%lld.%03lld", moment_key(seconds) / 1000, moment_key(seconds) % 1000);
  return name;
}

}  // namespace impulse::demos
