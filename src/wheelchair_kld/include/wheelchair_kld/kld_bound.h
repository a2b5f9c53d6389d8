// The sample-size bound of KLD-sampling (Fox 2003; paper Algorithm 1, line 14).
#pragma once

namespace wheelchair_kld {

/// Upper p-quantile of the standard normal: the z with P(Z <= z) = p, 0 < p < 1
/// (Acklam's rational approximation refined by one Halley step; |error| < 1e-12).
double standardNormalQuantile(double p);

/// Number of samples M_x so that, with probability 1 - delta, the K-L divergence between the
/// sample-based maximum-likelihood estimate and the true posterior over k non-empty bins is
/// below epsilon. Paper Algorithm 1 line 14 (Wilson-Hilferty approximation of the chi-square
/// quantile chi2_{k-1,1-delta} / (2 epsilon)), with z_{1-delta} the upper 1-delta quantile of
/// the standard normal (not delta itself, the listing's typo). Returns 0 for k <= 1.
double klBound(int k, double epsilon, double delta);

}  // namespace wheelchair_kld
