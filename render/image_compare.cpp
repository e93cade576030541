#include "render/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::render {
namespace {

constexpr double kLargestDelta = 35215.0;  // the largest YIQ delta of two colours, below (pixelmatch's)

double luma(const uint8_t* p) { return p[0] * 0.29889531 + p[1] * 0.58662247 + p[2] * 0.11448223; }
double in_phase(const uint8_t* p) { return p[0] * 0.59597799 - p[1] * 0.27417610 - p[2] * 0.32180189; }
double quadrature(const uint8_t* p) { return p[0] * 0.21147017 - p[1] * 0.52261711 + p[2] * 0.31114694; }

// Kotsarenko and Ramos's YIQ distance, squared and unscaled (0 .. kLargestDelta).
double yiq_delta(const uint8_t* a, const uint8_t* b) {
  if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0;
  const double y = luma(a) - luma(b), i = in_phase(a) - in_phase(b), q = quadrature(a) - quadrature(b);
  return 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
}

bool same_colour(const uint8_t* a, const uint8_t* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

struct View {
  const Frame& frame;
  const uint8_t* at(int x, int y) const { return frame.rgba.data() + (size_t(y) * frame.width + x) * 4; }
};

// Three or more of the 8 neighbours (the frame's edge counting as one) have its very colour: a
// flat area, not an anti-aliased edge.
bool has_many_siblings(const View& image, int x, int y) {
  const int width = image.frame.width, height = image.frame.height;
  int equal = (x == 0 || y == 0 || x == width - 1 || y == height - 1) ? 1 : 0;
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny)
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
      if ((nx == x && ny == y) || !same_colour(image.at(x, y), image.at(nx, ny))) continue;
      if (++equal > 2) return true;
    }
  return false;
}

// Vyšniauskas's anti-aliased pixel detector, as pixelmatch uses it: the pixel lies between a
// darker and a brighter neighbour, at most two neighbours share its colour, and the darkest or the
// brightest neighbour is inside a flat area in both frames.
bool anti_aliased(const View& image, const View& other, int x, int y) {
  const int width = image.frame.width, height = image.frame.height;
  int equal = (x == 0 || y == 0 || x == width - 1 || y == height - 1) ? 1 : 0;
  double darkest = 0, brightest = 0;
  int darkest_x = 0, darkest_y = 0, brightest_x = 0, brightest_y = 0;
  const double centre = luma(image.at(x, y));
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny)
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
      if (nx == x && ny == y) continue;
      const uint8_t* neighbour = image.at(nx, ny);
      if (same_colour(image.at(x, y), neighbour)) {
        if (++equal > 2) return false;
        continue;
      }
      const double brighter = luma(neighbour) - centre;
      if (brighter < darkest) {
        darkest = brighter;
        darkest_x = nx, darkest_y = ny;
      } else if (brighter > brightest) {
        brightest = brighter;
        brightest_x = nx, brightest_y = ny;
      }
    }
  if (darkest == 0 || brightest == 0) return false;
  return (has_many_siblings(image, darkest_x, darkest_y) && has_many_siblings(other, darkest_x, darkest_y)) ||
         (has_many_siblings(image, brightest_x, brightest_y) && has_many_siblings(other, brightest_x, brightest_y));
}

// The largest connected region (8 neighbours) of differing pixels and those whose verdict is `also`
// (differs again, or faint).
PixelRegion largest_region(const ImageDifference& difference, PixelVerdict also) {
  const int width = difference.width, height = difference.height;
  auto counts = [&](size_t index) {
    const PixelVerdict verdict = difference.verdicts[index];
    return verdict == PixelVerdict::differs || verdict == also;
  };
  std::vector<char> seen(difference.verdicts.size(), 0);
  std::vector<int> stack;
  PixelRegion largest;
  for (size_t start = 0; start < difference.verdicts.size(); ++start) {
    if (seen[start] || !counts(start)) continue;
    PixelRegion region{0, width, height, -1, -1};
    seen[start] = 1;
    stack.assign(1, int(start));
    while (!stack.empty()) {
      const int index = stack.back();
      stack.pop_back();
      const int x = index % width, y = index / width;
      ++region.pixels;
      region.left = std::min(region.left, x), region.right = std::max(region.right, x);
      region.top = std::min(region.top, y), region.bottom = std::max(region.bottom, y);
      for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny)
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
          const int next = ny * width + nx;
          if (seen[next] || !counts(size_t(next))) continue;
          seen[next] = 1;
          stack.push_back(next);
        }
    }
    if (region.pixels > largest.pixels) largest = region;
  }
  return largest;
}

std::string summarise(const ImageDifference& difference, const ImageTolerance& tolerance) {
  char text[400];
  const PixelRegion& faint = difference.largest_faint_region;
  if (faint.pixels > tolerance.max_faint_region_pixels && difference.largest_region <= tolerance.max_region_pixels) {
    std::snprintf(text, sizeof text,
                  "a faint difference over an area: %d touching pixels over a YIQ distance of %.2f (allowed: %d), "
                  "in x %d..%d, y %d..%d; %d pixels over %.2f; %d anti-aliased edge pixels forgiven",
                  faint.pixels, tolerance.faint_threshold, tolerance.max_faint_region_pixels, faint.left, faint.right,
                  faint.top, faint.bottom, difference.differing_pixels, tolerance.colour_threshold,
                  difference.anti_aliased_pixels);
  } else if (difference.differing_pixels == 0) {
    std::snprintf(text, sizeof text,
                  "no pixel differs (YIQ distance over %.2f), no region of more than %d over %.2f (largest: %d); %d "
                  "anti-aliased edge pixels forgiven",
                  tolerance.colour_threshold, tolerance.max_faint_region_pixels, tolerance.faint_threshold, faint.pixels,
                  difference.anti_aliased_pixels);
  } else {
    std::snprintf(text, sizeof text,
                  "largest region of differing pixels %d (allowed: %d), in x %d..%d, y %d..%d; %d pixels differ in all, "
                  "%.3f %% of the frame (allowed: %.3f %%); %d anti-aliased edge pixels forgiven",
                  difference.largest_region, tolerance.max_region_pixels, difference.left, difference.right,
                  difference.top, difference.bottom, difference.differing_pixels, 100 * difference.differing_share,
                  100 * tolerance.max_differing_share, difference.anti_aliased_pixels);
  }
  return text;
}

}  // namespace

double colour_distance(const uint8_t* a, const uint8_t* b) { return std::sqrt(yiq_delta(a, b) / kLargestDelta); }

ImageDifference compare_images(const Frame& expected, const Frame& actual, ImageTolerance tolerance) {
  ImageDifference difference;
  difference.same_size = expected.width == actual.width && expected.height == actual.height;
  difference.width = std::min(expected.width, actual.width);
  difference.height = std::min(expected.height, actual.height);
  difference.verdicts.assign(size_t(difference.width) * difference.height, PixelVerdict::same);
  if (!difference.same_size) {
    difference.summary = "the sizes differ: " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
                         " expected, " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " rendered";
    return difference;
  }
  const View a{expected}, b{actual};
  const double largest = kLargestDelta * tolerance.colour_threshold * tolerance.colour_threshold;
  const double faintest = kLargestDelta * tolerance.faint_threshold * tolerance.faint_threshold;
  for (int y = 0; y < difference.height; ++y)
    for (int x = 0; x < difference.width; ++x) {
      const double delta = yiq_delta(a.at(x, y), b.at(x, y));
      if (!(delta > faintest)) continue;
      const bool edge = anti_aliased(a, b, x, y) || anti_aliased(b, a, x, y);
      PixelVerdict& verdict = difference.verdicts[size_t(y) * difference.width + x];
      if (delta > largest) {
        verdict = edge ? PixelVerdict::anti_aliased : PixelVerdict::differs;
        ++(edge ? difference.anti_aliased_pixels : difference.differing_pixels);
      } else if (!edge) {  // a faint edge pixel is the same as below the faint threshold
        verdict = PixelVerdict::faint;
        ++difference.faint_pixels;
      }
    }
  difference.differing_share = double(difference.differing_pixels) / double(difference.verdicts.size());
  const PixelRegion differing = largest_region(difference, PixelVerdict::differs);
  difference.largest_region = differing.pixels;
  difference.left = differing.left, difference.top = differing.top;
  difference.right = differing.right, difference.bottom = differing.bottom;
  difference.largest_faint_region = largest_region(difference, PixelVerdict::faint);
  difference.matches = difference.largest_region <= tolerance.max_region_pixels &&
                       difference.differing_share <= tolerance.max_differing_share &&
                       difference.largest_faint_region.pixels <= tolerance.max_faint_region_pixels;
  difference.summary = summarise(difference, tolerance);
  return difference;
}

Frame difference_image(const Frame& expected, const Frame& actual, const ImageDifference& difference) {
  Frame diff;
  const int width = std::max(expected.width, actual.width), height = std::max(expected.height, actual.height);
  fill(diff, width, height, Colour{1.0f, 0.0f, 1.0f});  // magenta: only one frame has pixels here
  for (int y = 0; y < difference.height; ++y)
    for (int x = 0; x < difference.width; ++x) {
      uint8_t* out = diff.rgba.data() + (size_t(y) * width + x) * 4;
      const PixelVerdict verdict = difference.verdicts[size_t(y) * difference.width + x];
      if (verdict == PixelVerdict::differs) {
        out[0] = 255, out[1] = 0, out[2] = 0;
      } else if (verdict == PixelVerdict::faint) {
        out[0] = 255, out[1] = 140, out[2] = 170;
      } else if (verdict == PixelVerdict::anti_aliased) {
        out[0] = 255, out[1] = 210, out[2] = 0;
      } else {
        const uint8_t* in = expected.rgba.data() + (size_t(y) * expected.width + x) * 4;
        for (int c = 0; c < 3; ++c) out[c] = uint8_t(191 + in[c] / 4);
      }
    }
  return diff;
}

Frame side_by_side(const std::vector<const Frame*>& frames) {
  constexpr int kGap = 8;
  int width = kGap, height = 0;
  for (const Frame* frame : frames) {
    width += frame->width + kGap;
    height = std::max(height, frame->height);
  }
  Frame strip;
  fill(strip, width, height + 2 * kGap, Colour{0.5f, 0.5f, 0.5f});
  int x = kGap;
  for (const Frame* frame : frames) {
    paste(*frame, x, kGap, strip);
    x += frame->width + kGap;
  }
  return strip;
}

}  // namespace impulse::render
