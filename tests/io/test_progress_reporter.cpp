// The time-left estimate follows the recent pace of a run, not its average since the
// start (issue 12: "the ETA is a straight extrapolation").
#include <gtest/gtest.h>

#include "io/progress_reporter.hpp"

namespace cortex {
namespace {

TEST(RecentPace, NoEstimateBeforeTwoSamples) {
  RecentPace pace;
  EXPECT_LT(pace.secondsFor(1.0), 0.0);
  pace.add(0.0, 0.0);
  EXPECT_LT(pace.secondsFor(1.0), 0.0);
}

TEST(RecentPace, SteadyRunExtrapolatesItsPace) {
  RecentPace pace(60.0);
  for (int k = 0; k <= 10; ++k) pace.add(k, 0.1 * k);  // 0.1 simulated s per wall s
  EXPECT_NEAR(pace.secondsFor(1.0), 10.0, 1e-9);
}

TEST(RecentPace, FollowsARunThatSlowsDown) {
  // 1 simulated s per wall s for 50 s, then ten times slower (a vesicle shrinking to
  // where relaxations take longer). Over the last 10 s the pace is 0.1/s: 1 simulated s
  // takes 10 wall s; the average since the start (55 over 100 s) would say 1.8 s.
  RecentPace pace(10.0);
  double sim = 0.0;
  for (int wall = 0; wall <= 100; ++wall) {
    pace.add(wall, sim);
    sim += wall < 50 ? 1.0 : 0.1;
  }
  EXPECT_NEAR(pace.secondsFor(1.0), 10.0, 1e-6);
}

}  // namespace
}  // namespace cortex
