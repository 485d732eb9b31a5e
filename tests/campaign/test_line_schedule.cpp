// Who designs which line and who computes which statistics column, against the scheme written
// out by hand for 1, 2 and 3 processes.
#include <doctest/doctest.h>

#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "campaign/line_schedule.hpp"

using namespace growthuq;

TEST_CASE("serially the one process designs every line when it starts, nothing ahead") {
  const LineSchedule schedule(5, 1);
  for (std::size_t line = 0; line < 5; ++line) {
    CHECK(schedule.designer_of(line) == 0);
    CHECK(schedule.designed_at_start(line, 0) == std::vector<std::size_t>{line});
    CHECK_FALSE(schedule.designed_during_statistics(line).has_value());
  }
  // Greedy by least load, ties to the highest rank: with one process everything is rank 0's.
  CHECK(schedule.statistics_owners(0, {1.0, 0.25, 1.0}) == std::vector<int>{0, 0, 0});
}

TEST_CASE("with 3 processes lines 1, 2, 3, 4 are designed by ranks 1, 2, 1, 2, one line ahead") {
  const LineSchedule schedule(5, 3);
  CHECK(schedule.designer_of(0) == 0);
  CHECK(schedule.designer_of(1) == 1);
  CHECK(schedule.designer_of(2) == 2);
  CHECK(schedule.designer_of(3) == 1);
  CHECK(schedule.designer_of(4) == 2);
  // At the start rank 0 designs line 0 and rank 1 line 1, together; no one else designs then.
  CHECK(schedule.designed_at_start(0, 0) == std::vector<std::size_t>{0});
  CHECK(schedule.designed_at_start(0, 1) == std::vector<std::size_t>{1});
  CHECK(schedule.designed_at_start(0, 2).empty());
  for (std::size_t line = 1; line < 5; ++line) {
    for (int rank = 0; rank < 3; ++rank) CHECK(schedule.designed_at_start(line, rank).empty());
  }
  // Line i + 1 (i >= 1) is designed during line i's statistics; line 1 was made at the start.
  CHECK_FALSE(schedule.designed_during_statistics(0).has_value());
  CHECK(schedule.designed_during_statistics(1) == std::optional<std::size_t>(2));
  CHECK(schedule.designed_during_statistics(2) == std::optional<std::size_t>(3));
  CHECK(schedule.designed_during_statistics(3) == std::optional<std::size_t>(4));
  CHECK_FALSE(schedule.designed_during_statistics(4).has_value());
}

TEST_CASE("every line is designed exactly once, before it is shared, for 1 to 4 processes") {
  for (int processes = 1; processes <= 4; ++processes) {
    for (std::size_t lines = 1; lines <= 6; ++lines) {
      const LineSchedule schedule(lines, processes);
      std::vector<int> made(lines, 0);
      std::vector<int> maker(lines, -1);
      for (std::size_t line = 0; line < lines; ++line) {
        for (int rank = 0; rank < processes; ++rank) {
          for (const std::size_t designed : schedule.designed_at_start(line, rank)) {
            ++made[designed];
            maker[designed] = rank;
          }
        }
        CHECK(made[line] == 1);  // by the time line `line` is shared
        if (const std::optional<std::size_t> ahead = schedule.designed_during_statistics(line)) {
          ++made[*ahead];
          maker[*ahead] = schedule.designer_of(*ahead);
        }
      }
      for (std::size_t line = 0; line < lines; ++line) {
        CHECK(made[line] == 1);
        CHECK(maker[line] == schedule.designer_of(line));
        if (processes > 1 && line > 0) CHECK(schedule.designer_of(line) != 0);  // rank 0 coordinates
      }
    }
  }
}

TEST_CASE("statistics columns go to the least loaded process; the designer ahead takes none") {
  // 2 processes, line 1 of 3: rank 1 designs line 2 meanwhile, so rank 0 takes every column.
  CHECK(LineSchedule(3, 2).statistics_owners(1, {1.0, 1.0, 1.0}) == std::vector<int>{0, 0, 0});
  // Line 0 of 3 (line 1 was designed at the start): loads start at {0.5, 0}.
  //   column 0 (1.0) -> rank 1 (0 < 0.5): {0.5, 1}; column 1 (0.25) -> rank 0: {0.75, 1};
  //   column 2 (1.0) -> rank 0: {1.75, 1}; column 3 (0.25) -> rank 1: {1.75, 1.25}.
  CHECK(LineSchedule(3, 2).statistics_owners(0, {1.0, 0.25, 1.0, 0.25}) == std::vector<int>{1, 0, 0, 1});
  // 3 processes, line 2 of 5: rank 1 designs line 3, out; ties go to the highest rank.
  //   {0.5, -, 0}: c0 -> 2 {0.5, -, 1}; c1 -> 0 {1.5, -, 1}; c2 -> 2 {1.5, -, 2}; c3 -> 0.
  CHECK(LineSchedule(5, 3).statistics_owners(2, {1.0, 1.0, 1.0, 1.0}) == std::vector<int>{2, 0, 2, 0});
  // The last line: no design ahead, all three share. {0.5, 0, 0}: c0 -> 2 (tie with 1), c1 -> 1.
  CHECK(LineSchedule(5, 3).statistics_owners(4, {1.0, 1.0, 1.0}) == std::vector<int>{2, 1, 0});
  CHECK_THROWS_AS(LineSchedule(3, 0), std::invalid_argument);
}
