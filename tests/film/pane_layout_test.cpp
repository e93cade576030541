// Where a comparison's panes go (film.h, pane_layout).
#include "demos/film/film.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

namespace impulse {
namespace {

using demos::PaneLayout;

bool overlap(const PaneLayout& layout, size_t a, size_t b) {
  const Eigen::Vector2i& p = layout.origins[a];
  const Eigen::Vector2i& q = layout.origins[b];
  return p.x() < q.x() + layout.width && q.x() < p.x() + layout.width && p.y() < q.y() + layout.height &&
         q.y() < p.y() + layout.height;
}

// Two side by side, each of the frame's shape; three or four in a grid that fills the frame's
// width (beside the plots' column), each 1.2 to 2.4 times as wide as high.
TEST(PaneLayout, TwoSideBySideOfTheFramesShapeThreeOrFourInAGridThatFillsTheWidth) {
  const PaneLayout one = demos::pane_layout(1, 1280, 720, true, true);
  EXPECT_EQ(one.width, 1280);
  EXPECT_EQ(one.height, 720);
  for (const bool captions : {false, true}) {
    for (const bool plots : {false, true}) {
      for (const int panes : {2, 3, 4}) {
        SCOPED_TRACE(std::to_string(panes) + (plots ? " panes, plots" : " panes") + (captions ? ", captions" : ""));
        const PaneLayout layout = demos::pane_layout(panes, 1280, 720, plots, captions);
        ASSERT_EQ(layout.origins.size(), size_t(panes));
        if (panes == 2) {
          EXPECT_NEAR(double(layout.width) / layout.height, 1280.0 / 720.0, 0.02);
        } else {
          EXPECT_GE(double(layout.width) / layout.height, 1.2);
          EXPECT_LE(double(layout.width) / layout.height, 2.4);
          // No margins at the sides: two columns and three gaps of 8 px fill the width left.
          EXPECT_GE(2 * layout.width + 3 * 8, (plots ? 1280 - 300 : 1280) - 2);
        }
        EXPECT_GE(layout.width, 460);  // more than a third of the frame
        // Under one row, or with captions under four panes, a band of two caption lines (100 px) is
        // left free; three leave the grid's fourth cell for them.
        const int bottom = panes == 2 || (captions && panes == 4) ? 720 - 100 : 720;
        for (size_t i = 0; i < layout.origins.size(); ++i) {
          const Eigen::Vector2i& at = layout.origins[i];
          EXPECT_GE(at.x(), 0);
          EXPECT_GE(at.y(), 72);  // under the title and the clock
          EXPECT_LE(at.x() + layout.width, plots && panes > 2 ? 1280 - 300 : 1280);  // the plots' column
          EXPECT_LE(at.y() + layout.height, bottom);
          for (size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(layout, i, j)) << i << " and " << j;
        }
        EXPECT_EQ(layout.origins[1].y(), layout.origins[0].y());  // side by side
        if (panes > 2) {
          EXPECT_GT(layout.origins[2].y(), layout.origins[0].y());
        }
        if (plots && panes == 2) {  // a row of plots (88 px high) under the panes
          EXPECT_GE(layout.plots_row_top, layout.origins[0].y() + layout.height);
          EXPECT_LE(layout.plots_row_top + 88, bottom);
        } else {
          EXPECT_LT(layout.plots_row_top, 0);
        }
      }
    }
  }
}

}  // namespace
}  // namespace impulse
