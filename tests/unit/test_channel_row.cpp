// ChannelRow (model/channel.hpp): the channels of one output row may share a costly
// evaluation; a joint's six reaction components (Joint::add_channels) come from one reaction
// per row. What is asserted: inside a row the values are those computed outside any row
// (bit for bit: the same function of the same state), a later row of a changed state gets
// the changed values (nothing kept from the earlier row), a row nested in another and the
// rows of two threads reading the same model's channels at once each get their own state's
// values. The reference is the reaction's linearity in the multipliers: scaling lambda by k
// scales every component by k (Joint::reaction sums mu_r times the factors).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <barrier>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/model/channel.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

// a 10 kg box hanging from a ball joint "hook" 1 m above its centre, pushed sideways by a
// constant force: in statics the joint carries the weight and the side force (three
// nonzero components)
const std::string kModel = R"(environment: {gravity: 9.81}
bodies:
  box: {type: rigid_body, mass: 10, inertia: [1, 1, 1], position: [0, 0, -1]}
joints:
  - {name: hook, type: ball, from: {body: ground, position: [0, 0, 0]},
     to: {body: box, position: [0, 0, 1]}}
loads:
  - {type: point_force, at: {body: box}, force: [30, -20, 0]}
)";

std::array<double, 6> hook(const ChannelList& channels, const State& s) {
  static const char* names[] = {"hook.fx", "hook.fy", "hook.fz", "hook.mx", "hook.my", "hook.mz"};
  std::array<double, 6> out{};
  for (int i = 0; i < 6; ++i) {
    const auto it = std::find_if(channels.begin(), channels.end(),
                                 [&](const Channel& c) { return c.name == names[i]; });
    EXPECT_NE(it, channels.end()) << names[i];
    if (it != channels.end()) out[static_cast<std::size_t>(i)] = it->value(s);
  }
  return out;
}

}  // namespace

TEST(ChannelRow, AJointsReactionIsSharedWithinARowAndNotKeptAcrossRows) {
  io::Model m = io::load_model_text(kModel, "m.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const ChannelList channels = m.system->channels();
  EXPECT_EQ(ChannelRow::current(), 0);
  const std::array<double, 6> alone = hook(channels, s);
  // statics: the joint holds the box's weight and the side force (signs as the channels
  // give them); at least two components well away from zero
  EXPECT_NEAR(std::abs(alone[2]), 10 * 9.81, 1e-6);
  EXPECT_NEAR(std::hypot(alone[0], alone[1]), std::hypot(30.0, 20.0), 1e-6);
  {
    const ChannelRow row;
    EXPECT_NE(ChannelRow::current(), 0);
    const std::array<double, 6> in_row = hook(channels, s);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(in_row[i], alone[i]) << i;
  }
  EXPECT_EQ(ChannelRow::current(), 0);
  State doubled = s;
  doubled.lambda *= 2.0;
  {
    const ChannelRow row;  // a new row: the changed state's values, not the last row's
    const std::array<double, 6> in_row = hook(channels, doubled);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(in_row[i], 2.0 * alone[i], 1e-12 * 300) << i;
    {
      const ChannelRow inner;  // nested: its own values
      State tripled = s;
      tripled.lambda *= 3.0;
      const std::array<double, 6> v = hook(channels, tripled);
      for (int i = 0; i < 6; ++i) EXPECT_NEAR(v[i], 3.0 * alone[i], 1e-12 * 300) << i;
    }
    // back in the outer row, after the inner one took the shared evaluation: the outer
    // state's values again
    const std::array<double, 6> again = hook(channels, doubled);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(again[i], 2.0 * alone[i], 1e-12 * 300) << i;
  }
}

TEST(ChannelRow, RowsOfTwoThreadsOnTheSameChannelsKeepTheirOwnValues) {
  io::Model m = io::load_model_text(kModel, "m.yaml");
  State s = m.system->initial_state();
  solve_statics(*m.system, s, m.statics);
  const ChannelList channels = m.system->channels();
  const std::array<double, 6> alone = hook(channels, s);
  std::atomic<int> wrong{0};
  // the two threads take their rows in step (a barrier before each), so that a row number
  // shared between threads would hand one thread the other's reaction
  std::barrier step(2);
  auto work = [&](double k) {
    State mine = s;
    mine.lambda *= k;
    for (int n = 0; n < 2000; ++n) {
      step.arrive_and_wait();
      const ChannelRow row;
      const std::array<double, 6> v = hook(channels, mine);
      for (int i = 0; i < 6; ++i)
        if (std::abs(v[static_cast<std::size_t>(i)] - k * alone[static_cast<std::size_t>(i)]) >
            1e-12 * 300)
          ++wrong;
    }
  };
  std::thread a(work, 1.0), b(work, 3.0);
  a.join();
  b.join();
  EXPECT_EQ(wrong.load(), 0);
}
