#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>

#include "hair/core/progress.h"

namespace {

using Clock = hair::ProgressOutput::Clock;
using std::chrono::milliseconds;

/// A Progress output into a string, on a clock the test moves by hand.
struct FakeOutput {
  std::ostringstream text;
  Clock::time_point now{};

  hair::ProgressOutput output(bool is_terminal, bool enabled = true) {
    hair::ProgressOutput result;
    result.stream = &text;
    result.is_terminal = is_terminal;
    result.enabled = enabled;
    result.line_prefix = "stage: ";
    result.now = [this] { return now; };
    return result;
  }
};

TEST(Progress, SilentForWorkUnderOneSecond) {
  for (const bool is_terminal : {false, true}) {
    FakeOutput fake;
    hair::Progress progress("quick", 100, fake.output(is_terminal));
    for (int step = 0; step < 100; ++step) {
      fake.now += milliseconds(9);
      progress.advance();
    }
    progress.finish();
    EXPECT_EQ(fake.text.str(), "");
  }
}

TEST(Progress, LinesEveryTenthAfterOneSecondWhenNotATerminal) {
  FakeOutput fake;
  hair::Progress progress("growing", 100, fake.output(false));
  fake.now += milliseconds(500);
  progress.advance(30);  // before one second: nothing
  fake.now += milliseconds(600);
  progress.advance(10);  // 40%
  fake.now += milliseconds(50);
  progress.advance(20);  // 60% but within 200 ms of the last report: nothing
  fake.now += milliseconds(200);
  progress.advance(5);  // 65%
  fake.now += milliseconds(200);
  progress.advance(1);  // 66%: still the same tenth
  fake.now += milliseconds(650);
  progress.finish();
  EXPECT_EQ(fake.text.str(),
            "stage: growing: 40% (40/100)\n"
            "stage: growing: 65% (65/100)\n"
            "stage: growing: 66% (66/100) in 2.2 s\n");
}

TEST(Progress, RedrawsOneLineOnATerminal) {
  FakeOutput fake;
  hair::Progress progress("frames", 1000, fake.output(true));
  fake.now += milliseconds(1000);
  progress.advance(450);
  fake.now += milliseconds(100);
  progress.advance(1);  // too soon to redraw
  fake.now += milliseconds(150);
  progress.advance(549);
  progress.finish();
  EXPECT_EQ(fake.text.str(),
            "\rstage: frames: 45% (450/1000)"
            "\rstage: frames: 100% (1000/1000)"
            "\rstage: frames: 100% (1000/1000) in 1.2 s\n");
}

TEST(Progress, QuietPrintsNothing) {
  FakeOutput fake;
  hair::Progress progress("strands", 10, fake.output(false, false));
  fake.now += milliseconds(5000);
  progress.advance(10);
  progress.finish();
  EXPECT_EQ(fake.text.str(), "");
}

TEST(Progress, CountsEveryAdvanceFromManyThreads) {
  FakeOutput fake;
  hair::Progress progress("parallel", 100000, fake.output(false));
  fake.now += milliseconds(1500);  // the clock stands still while the threads run
#pragma omp parallel for
  for (int item = 0; item < 100000; ++item) progress.advance();
  progress.finish();
  const std::string text = fake.text.str();
  EXPECT_NE(text.find("stage: parallel: 100% (100000/100000) in 1.5 s\n"), std::string::npos)
      << text;
}

TEST(Progress, DestructorFinishesAndFinishIsIdempotent) {
  FakeOutput fake;
  {
    hair::Progress progress("scoped", 4, fake.output(false));
    fake.now += milliseconds(1200);
    progress.advance(4);
    progress.finish();
    progress.finish();
  }
  EXPECT_EQ(fake.text.str(),
            "stage: scoped: 100% (4/4)\n"
            "stage: scoped: 100% (4/4) in 1.2 s\n");

  FakeOutput unfinished;
  {
    hair::Progress progress("scoped", 4, unfinished.output(false));
    unfinished.now += milliseconds(1000);
  }
  EXPECT_EQ(unfinished.text.str(), "stage: scoped: 0% (0/4) in 1.0 s\n");
}

TEST(Progress, UnwindingOnlyEndsTheTerminalLine) {
  FakeOutput fake;
  try {
    hair::Progress progress("failing", 10, fake.output(true));
    fake.now += milliseconds(1100);
    progress.advance(3);
    throw std::runtime_error("failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(fake.text.str(), "\rstage: failing: 30% (3/10)\n");
}

}  // namespace
