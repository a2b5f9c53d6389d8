// klBound (Algorithm 1, line 14) against tabulated chi-square quantiles, and the normal quantile.
#include <gtest/gtest.h>
#include <wheelchair_kld/kld_bound.h>

using wheelchair_kld::klBound;
using wheelchair_kld::standardNormalQuantile;

TEST(StandardNormalQuantile, MatchesTabulatedValues) {
  EXPECT_NEAR(standardNormalQuantile(0.99), 2.326348, 1e-6);  // z_{1-delta}, delta = 0.01
  EXPECT_NEAR(standardNormalQuantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(standardNormalQuantile(0.95), 1.644854, 1e-6);
  EXPECT_NEAR(standardNormalQuantile(0.5), 0.0, 1e-9);
  EXPECT_NEAR(standardNormalQuantile(0.001), -3.090232, 1e-6);
  EXPECT_NEAR(standardNormalQuantile(1e-9), -5.997807, 1e-5);
  EXPECT_THROW(standardNormalQuantile(0.0), std::invalid_argument);
  EXPECT_THROW(standardNormalQuantile(1.0), std::invalid_argument);
}

// M_x = chi2_{k-1, 1-delta} / (2 epsilon); chi-square quantiles from standard tables
// (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
TEST(KlBound, MatchesChiSquareTableOverTwoEpsilon) {
  struct Row {
    int df;
    double p99, p95;
  };
  const Row table[] = {{2, 9.210, 5.991},    {5, 15.086, 11.070},  {10, 23.209, 18.307},
                       {20, 37.566, 31.410}, {50, 76.154, 67.505}, {100, 135.807, 124.342}};
  for (const Row& r : table) {
    const double eps = 0.05;
    const double tol = r.df < 5 ? 0.02 : 0.005;  // Wilson-Hilferty's relative accuracy
    EXPECT_NEAR(klBound(r.df + 1, eps, 0.01), r.p99 / (2 * eps), tol * r.p99 / (2 * eps))
        << "df " << r.df;
    EXPECT_NEAR(klBound(r.df + 1, eps, 0.05), r.p95 / (2 * eps), tol * r.p95 / (2 * eps))
        << "df " << r.df;
  }
}

TEST(KlBound, ScalesInverselyWithEpsilonAndGrowsWithBins) {
  EXPECT_DOUBLE_EQ(klBound(1, 0.05, 0.01), 0.0);
  EXPECT_NEAR(klBound(30, 0.025, 0.01), 2 * klBound(30, 0.05, 0.01), 1e-9);
  EXPECT_GT(klBound(31, 0.05, 0.01), klBound(30, 0.05, 0.01));
  // Smaller delta (more confidence) needs more samples: the listing's "z = delta" bug would
  // make it the other way round.
  EXPECT_GT(klBound(30, 0.05, 0.01), klBound(30, 0.05, 0.1));
}
