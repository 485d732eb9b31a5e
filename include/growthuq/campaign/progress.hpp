// Progress of a campaign run on stderr: a bar with samples done, rate and time left when stderr
// is a terminal; otherwise (logs, batch jobs) one line per finished plant line, and a line with
// samples done, rate and time left at most every 30 s while a line runs; nothing when
// the user asked for quiet. The same for the counted steps around the sampling (raw-data curve
// fits, the data-uncertainty bootstrap).
#pragma once

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>

#include "growthuq/campaign/progress_mode.hpp"

namespace growthuq {

class Progress {
 public:
  // `total_samples` over all lines, for the overall rate and time left.
  Progress(ProgressMode mode, std::ostream& out, std::size_t total_samples);

  void line_started(std::string_view line, std::size_t samples);
  void advance(std::size_t samples);
  // Samples a resumed run took from its checkpoint: done, but not counted in the rate.
  void advance_replayed(std::size_t samples);
  // Ends the line: clears the bar, or prints "<line>: N samples in T s (R samples/s)".
  void line_finished();
  // The run stopped before the line finished: clears the bar so the next message starts clean.
  void stopped();

 private:
  using Clock = std::chrono::steady_clock;
  void draw_bar(bool force);

  ProgressMode mode_;
  std::ostream& out_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::size_t replayed_ = 0;  // of done_
  std::string line_;
  std::size_t line_samples_ = 0;
  std::size_t line_done_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point line_start_ = start_;
  Clock::time_point last_draw_{};
};

// Progress of a counted step that is not sampling: "<label>: <item> 120/400, 4 s, about 9 s
// left" as a bar on a terminal (redrawn at most ten times a second), as such a line every few
// seconds otherwise; either way "<label>: 400 <item>s in 10.2 s" when done.
class StepProgress {
 public:
  StepProgress(ProgressMode mode, std::ostream& out, std::string label, std::string item, std::size_t total);

  void advance(std::size_t items = 1);
  // Clears the bar and prints the line with the time the step took.
  void finish();
  // Clears the bar and prints nothing (the caller reports the outcome itself).
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  std::string status(Clock::time_point now) const;

  ProgressMode mode_;
  std::ostream& out_;
  std::string label_;
  std::string item_;
  std::size_t total_;
  std::size_t done_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_ = start_;
};

}  // namespace growthuq
