#include <gtest/gtest.h>
#include <wheelchair_display/contrast.h>
#include <wheelchair_display/theme.h>

namespace wheelchair_display {

TEST(Contrast, BlackOnWhiteIsTwentyOneToOne) {
  EXPECT_NEAR(contrastRatio(rgbFromHex("#000000"), rgbFromHex("#FFFFFF")), 21.0, 1e-9);
  EXPECT_NEAR(contrastRatio(rgbFromHex("#FFFFFF"), rgbFromHex("#000000")), 21.0, 1e-9);
  EXPECT_NEAR(contrastRatio(rgbFromHex("#777777"), rgbFromHex("#777777")), 1.0, 1e-12);
}

TEST(Contrast, MatchesWcagReferenceValues) {
  // WebAIM's checker: #767676 on white 4.54:1 (the lightest AA grey), #595959 on white 7.0:1.
  EXPECT_NEAR(contrastRatio(rgbFromHex("#767676"), rgbFromHex("#FFFFFF")), 4.54, 0.01);
  EXPECT_NEAR(contrastRatio(rgbFromHex("#595959"), rgbFromHex("#FFFFFF")), 7.0, 0.01);
  EXPECT_NEAR(relativeLuminance(rgbFromHex("#FF0000")), 0.2126, 1e-4);
}

TEST(Contrast, HexRoundTripsAndRejectsOtherShapes) {
  EXPECT_EQ(toHex(rgbFromHex("#1a2B3c")), "#1A2B3C");
  EXPECT_THROW(rgbFromHex("1A2B3C"), std::invalid_argument);
  EXPECT_THROW(rgbFromHex("#12345G"), std::invalid_argument);
  EXPECT_THROW(rgbFromHex("#123"), std::invalid_argument);
}

TEST(Theme, EveryPairOfBothThemesHasTheContrastItNeeds) {
  for (const Theme& theme : {darkTheme(), lightTheme()}) {
    for (const ContrastPair& pair : contrastPairs(theme))
      EXPECT_GE(pair.ratio(), pair.required)
          << theme.name << ": " << pair.what << " " << toHex(pair.foreground) << " on "
          << toHex(pair.background);
  }
}

TEST(Theme, TheStatusLineNeedsSevenToOneAndAllTextFourAndAHalf) {
  const auto pairs = contrastPairs(darkTheme());
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(pairs.front().what, "status text on status background");
  EXPECT_EQ(pairs.front().required, 7.0);
  for (const auto& pair : pairs) EXPECT_GE(pair.required, 3.0) << pair.what;
}

TEST(Theme, IsChosenByNameAndAnUnknownNameIsRefused) {
  EXPECT_EQ(themeNamed("light").name, "light");
  EXPECT_EQ(themeNamed("dark").name, "dark");
  EXPECT_THROW(themeNamed("blue"), std::invalid_argument);
}

}  // namespace wheelchair_display
