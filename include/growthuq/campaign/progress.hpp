// Progress of a campaign run on stderr: a bar with samples done, rate and time left when stderr
// is a terminal; one line per finished plant line otherwise (logs, batch jobs); nothing when
// the user asked for quiet.
#pragma once

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>

namespace growthuq {

enum class ProgressMode { none, lines, bar };

// bar when stderr is a terminal, lines otherwise, none when `quiet`.
ProgressMode choose_progress_mode(bool quiet);

class Progress {
 public:
  // `total_samples` over all lines, for the overall rate and time left.
  Progress(ProgressMode mode, std::ostream& out, std::size_t total_samples);

  void line_started(std::string_view line, std::size_t samples);
  void advance(std::size_t samples);
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
  std::string line_;
  std::size_t line_samples_ = 0;
  std::size_t line_done_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point line_start_ = start_;
  Clock::time_point last_draw_{};
};

}  // namespace growthuq
