#include <gtest/gtest.h>
#include <wheelchair_display/layout.h>

namespace wheelchair_display {

class LayoutSizes : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(LayoutSizes, TheStatusFontIsAtLeast48PxAndTheRegionsTileTheScreen) {
  const auto [w, h] = GetParam();
  for (bool with_list : {false, true}) {
    const Layout l = computeLayout(w, h, with_list);
    EXPECT_GE(l.status_font_px, 48);
    EXPECT_GE(l.stop_font_px, 48);
    EXPECT_GE(l.label_font_px, 24);
    // The STOP area runs the whole height of the right edge.
    EXPECT_EQ(l.stop.y, 0);
    EXPECT_EQ(l.stop.h, h);
    EXPECT_EQ(l.stop.right(), w);
    EXPECT_GE(l.stop.w, 160);
    // Status above, prompt below, list and map between, nothing overlapping the STOP area.
    EXPECT_EQ(l.status.bottom(), l.map.y);
    EXPECT_EQ(l.map.bottom(), l.prompt.y);
    EXPECT_EQ(l.prompt.bottom(), h);
    EXPECT_EQ(l.map.right(), l.stop.x);
    EXPECT_EQ(l.list.right(), l.map.x);
    EXPECT_EQ(with_list, l.list.w > 0);
    EXPECT_GE(l.status.h, 2 * l.status_font_px);  // room for two lines
    EXPECT_GT(l.map.h, h / 3);
    // The Go button sits in the prompt bar, apart from the carer's small button.
    EXPECT_TRUE(l.go_button.y >= l.prompt.y && l.go_button.bottom() <= l.prompt.bottom());
    EXPECT_FALSE(l.go_button.intersects(l.carer_button));
    EXPECT_LT(l.carer_button.w, l.go_button.w / 2);
  }
}

INSTANTIATE_TEST_SUITE_P(ChairScreens, LayoutSizes,
                         ::testing::Values(std::make_pair(1024, 768), std::make_pair(1920, 1080),
                                           std::make_pair(800, 600)));

TEST(Layout, FontsGrowWithTheScreen) {
  EXPECT_GT(computeLayout(1920, 1080, false).status_font_px,
            computeLayout(1024, 768, false).status_font_px);
}

}  // namespace wheelchair_display
