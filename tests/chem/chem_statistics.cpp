#include "chem_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cortex::chemtest {

namespace {

// Regularized upper incomplete gamma Q(a, x): series below a + 1, continued fraction
// (modified Lentz) above, as in Numerical Recipes 6.2.
double gammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000 && std::abs(term) > 1e-16 * std::abs(sum); ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1.0 - sum * std::exp(log_prefactor);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(log_prefactor) * h;
}

}  // namespace

double chiSquarePValue(double statistic, int dof) { return gammaQ(0.5 * dof, 0.5 * statistic); }

std::vector<long> histogram(const std::vector<int>& samples) {
  std::vector<long> counts(samples.empty() ? 0 : *std::max_element(samples.begin(), samples.end()) + 1, 0);
  for (int s : samples) {
    if (s < 0) throw std::invalid_argument("histogram: negative copy number " + std::to_string(s));
    ++counts[s];
  }
  return counts;
}

ChiSquare goodnessOfFit(const std::vector<int>& samples, const std::function<double(int)>& probability) {
  const std::vector<long> counts = histogram(samples);
  const double n = static_cast<double>(samples.size());
  std::vector<double> observed, expected;
  double obs = 0.0, exp = 0.0, cumulative = 0.0;
  for (int v = 0; (cumulative < 1.0 - 1e-12 && v < 1000000) || v < static_cast<int>(counts.size()); ++v) {
    const double p = probability(v);
    cumulative += p;
    obs += v < static_cast<int>(counts.size()) ? counts[v] : 0;
    exp += n * p;
    if (exp >= 5.0) {
      observed.push_back(obs);
      expected.push_back(exp);
      obs = exp = 0.0;
    }
  }
  // The tail beyond the last value summed belongs to the last bin, as does a last bin
  // expecting fewer than 5.
  exp += n * std::max(0.0, 1.0 - cumulative);
  observed.back() += obs;
  expected.back() += exp;
  ChiSquare r;
  for (std::size_t i = 0; i < observed.size(); ++i)
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
  r.dof = static_cast<int>(observed.size()) - 1;
  r.p = chiSquarePValue(r.statistic, r.dof);
  return r;
}

ChiSquare twoSample(const std::vector<int>& a, const std::vector<int>& b) {
  const std::vector<long> ha = histogram(a), hb = histogram(b);
  const std::size_t size = std::max(ha.size(), hb.size());
  std::vector<double> ba, bb;
  double ca = 0.0, cb = 0.0;
  for (std::size_t v = 0; v < size; ++v) {
    ca += v < ha.size() ? ha[v] : 0;
    cb += v < hb.size() ? hb[v] : 0;
    if (ca + cb >= 10.0) {
      ba.push_back(ca);
      bb.push_back(cb);
      ca = cb = 0.0;
    }
  }
  ba.back() += ca;
  bb.back() += cb;
  const double ra = std::sqrt(static_cast<double>(b.size()) / a.size());
  ChiSquare r;
  for (std::size_t i = 0; i < ba.size(); ++i) {
    const double d = ra * ba[i] - bb[i] / ra;
    r.statistic += d * d / (ba[i] + bb[i]);
  }
  r.dof = static_cast<int>(ba.size()) - 1;
  r.p = chiSquarePValue(r.statistic, r.dof);
  return r;
}

Moments moments(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  Moments m;
  for (double v : x) m.mean += v;
  m.mean /= n;
  double m2 = 0.0, m4 = 0.0;
  for (double v : x) {
    const double d2 = (v - m.mean) * (v - m.mean);
    m2 += d2;
    m4 += d2 * d2;
  }
  m.variance = m2 / (n - 1.0);
  m.standardError = std::sqrt(m.variance / n);
  m.varianceError = std::sqrt(std::max(0.0, m4 / n - (m2 / n) * (m2 / n)) / n);
  return m;
}

Moments moments(const std::vector<int>& samples) {
  return moments(std::vector<double>(samples.begin(), samples.end()));
}

double lagOneCorrelation(const std::vector<int>& samples) {
  const Moments m = moments(samples);
  double c = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i) c += (samples[i] - m.mean) * (samples[i - 1] - m.mean);
  return c / ((samples.size() - 1) * m.variance);
}

}  // namespace cortex::chemtest
