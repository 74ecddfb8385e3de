// SPDX-License-Identifier: MIT
// The loop's pace (wall seconds per simulated ms) counts only the steps it ran: a resumed run or a second stage
// reports its own cost, not its wall time over the whole run's simulated time.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "common/time_loop.hpp"

namespace {

TEST(TimeLoopPace, IsZeroBeforeAnyStep) {
  const hs::common::TimeLoop loop(10, 5);
  EXPECT_EQ(loop.wall_s_per_simulated_ms(1e-3), 0.0);
}

TEST(TimeLoopPace, CountsOnlyTheStepsOfAResumedLoop) {
  // Resumed at step 1000; one step of 1 ms simulated that takes at least 5 ms of wall time: at least 0.005 wall s per
  // simulated ms (sleep_for waits at least as long). Counted from step 0 it would be ~1000 times less.
  hs::common::TimeLoop loop(1001, 1000);
  loop.add("slow_stage", [] { std::this_thread::sleep_for(std::chrono::milliseconds(5)); });
  loop.run();
  EXPECT_EQ(loop.step(), 1001);
  EXPECT_GE(loop.wall_s_per_simulated_ms(1e-3), 0.005);
}

}  // namespace
