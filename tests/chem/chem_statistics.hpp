// Statistics for the stochastic chemistry tests: chi-square p-values, goodness of fit
// against a known distribution, and a two-sample test between two engines.
//
// Every test feeds these with samples spaced several relaxation times apart, so the
// samples are independent and the statistics have their nominal distributions.
#pragma once

#include <functional>
#include <vector>

namespace cortex::chemtest {

// P(chi^2 with `dof` degrees of freedom > statistic).
double chiSquarePValue(double statistic, int dof);

struct ChiSquare {
  double statistic = 0.0;
  int dof = 0;
  double p = 1.0;
};

// Histogram of integer samples: counts[n] = how many samples equal n.
std::vector<long> histogram(const std::vector<int>& samples);

// Pearson goodness of fit of the samples to the distribution `probability(n)`, n >= 0;
// bins are merged until each expects >= 5 samples, the last bin takes the whole tail.
ChiSquare goodnessOfFit(const std::vector<int>& samples, const std::function<double(int)>& probability);

// Two-sample chi-square test (Press et al., Numerical Recipes 14.3, unequal sizes) that
// both sample sets come from one distribution; bins merged until each holds >= 10.
ChiSquare twoSample(const std::vector<int>& a, const std::vector<int>& b);

struct Moments {
  double mean = 0.0;
  double variance = 0.0;       // unbiased
  double standardError = 0.0;  // of the mean
  double varianceError = 0.0;  // of the variance: sqrt((m4 - var^2) / n)
};
Moments moments(const std::vector<double>& samples);
Moments moments(const std::vector<int>& samples);

// Lag-1 autocorrelation: checks that samples are spaced far enough to be independent.
double lagOneCorrelation(const std::vector<int>& samples);

}  // namespace cortex::chemtest
