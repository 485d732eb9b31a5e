#include "growthuq/campaign/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace growthuq {
namespace {

// "1.2e+04"-style rates read badly in a bar; three significant digits suffice.
std::string rate_text(double per_second) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", per_second);
  return text;
}

std::string duration_text(double seconds) {
  if (!(seconds >= 0) || seconds > 360000) return "--:--";
  const auto whole = static_cast<long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", whole / 60, whole % 60);
  return text;
}

// "[#########.....................] " for a fraction done.
std::string bar_of(double fraction) {
  constexpr int width = 30;
  const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * width);
  return "[" + std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(width - filled), '.') + "] ";
}

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

ProgressMode choose_progress_mode(bool quiet) {
  if (quiet) return ProgressMode::none;
  return isatty(STDERR_FILENO) != 0 ? ProgressMode::bar : ProgressMode::lines;
}

Progress::Progress(ProgressMode mode, std::ostream& out, std::size_t total_samples)
    : mode_(mode), out_(out), total_(total_samples) {}

void Progress::line_started(std::string_view line, std::size_t samples) {
  line_ = std::string(line);
  line_samples_ = samples;
  line_done_ = 0;
  line_start_ = Clock::now();
  draw_bar(true);
}

void Progress::advance(std::size_t samples) {
  done_ += samples;
  line_done_ += samples;
  draw_bar(false);
}

void Progress::advance_replayed(std::size_t samples) {
  replayed_ += samples;
  advance(samples);
}

void Progress::line_finished() {
  const double seconds = seconds_between(line_start_, Clock::now());
  if (mode_ == ProgressMode::bar) {
    out_ << "\r\033[K" << std::flush;
  }
  if (mode_ != ProgressMode::none) {
    char timing[64];
    std::snprintf(timing, sizeof timing, "%.3g s", seconds);
    out_ << line_ << ": " << line_done_ << " samples in " << timing;
    if (seconds > 0) out_ << " (" << rate_text(static_cast<double>(line_done_) / seconds) << " samples/s)";
    out_ << "\n" << std::flush;
  }
}

void Progress::stopped() {
  if (mode_ == ProgressMode::bar) out_ << "\r\033[K" << std::flush;
}

void Progress::draw_bar(bool force) {
  if (mode_ == ProgressMode::none) return;
  const Clock::time_point now = Clock::now();
  if (mode_ == ProgressMode::lines) {
    // A log gets a line at most every 30 s, so that a run whose lines take minutes (fidelity
    // shell_fe: minutes per sample) shows it is alive, and how long it has left, without
    // filling the log; a line that starts does not count as progress.
    if (force || done_ == 0) {
      if (done_ == 0) last_draw_ = now;
      return;
    }
    if (seconds_between(last_draw_, now) < 30.0 || done_ >= total_) return;
    last_draw_ = now;
    const double elapsed = seconds_between(start_, now);
    const double rate = elapsed > 0 ? static_cast<double>(done_ - replayed_) / elapsed : 0.0;
    out_ << "progress: " << done_ << "/" << total_ << " samples, line " << line_ << " " << line_done_ << "/"
         << line_samples_ << ", " << rate_text(rate) << " samples/s, about " << duration_text(static_cast<double>(total_ - done_) / rate)
         << " left\n" << std::flush;
    return;
  }
  // Redrawing more than ten times a second only costs time.
  if (!force && seconds_between(last_draw_, now) < 0.1 && done_ < total_) return;
  last_draw_ = now;
  constexpr int width = 30;
  const double fraction = total_ == 0 ? 1.0 : static_cast<double>(done_) / static_cast<double>(total_);
  const int filled = static_cast<int>(fraction * width);
  const double elapsed = seconds_between(start_, now);
  const double rate = elapsed > 0 ? static_cast<double>(done_ - replayed_) / elapsed : 0.0;
  const double left = rate > 0 ? static_cast<double>(total_ - done_) / rate : -1.0;
  out_ << "\r\033[K[" << std::string(static_cast<std::size_t>(filled), '#')
       << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << done_ << "/" << total_ << " samples  "
       << line_ << "  " << rate_text(rate) << "/s  left " << duration_text(left) << std::flush;
}

StepProgress::StepProgress(ProgressMode mode, std::ostream& out, std::string label, std::string item, std::size_t total)
    : mode_(mode), out_(out), label_(std::move(label)), item_(std::move(item)), total_(total) {
  if (mode_ == ProgressMode::bar) out_ << "\r\033[K" << bar_of(0.0) << status(start_) << std::flush;
}

void StepProgress::advance(std::size_t items) {
  done_ += items;
  if (mode_ == ProgressMode::none) return;
  const Clock::time_point now = Clock::now();
  // A bar is redrawn at most ten times a second; a log gets a line every five seconds, so a
  // long step shows it is alive without filling the log.
  const double interval = mode_ == ProgressMode::bar ? 0.1 : 5.0;
  if (seconds_between(last_draw_, now) < interval) return;
  last_draw_ = now;
  if (mode_ == ProgressMode::bar) {
    const double fraction = total_ == 0 ? 1.0 : static_cast<double>(done_) / static_cast<double>(total_);
    out_ << "\r\033[K" << bar_of(fraction) << status(now) << std::flush;
  } else {
    out_ << status(now) << "\n" << std::flush;
  }
}

void StepProgress::finish() {
  if (mode_ == ProgressMode::none) return;
  if (mode_ == ProgressMode::bar) out_ << "\r\033[K";
  char timing[64];
  std::snprintf(timing, sizeof timing, "%.3g s", seconds_between(start_, Clock::now()));
  out_ << label_ << ": " << done_ << " " << item_ << (done_ == 1 ? "" : "s") << " in " << timing << "\n" << std::flush;
}

void StepProgress::clear() {
  if (mode_ == ProgressMode::bar) out_ << "\r\033[K" << std::flush;
}

std::string StepProgress::status(Clock::time_point now) const {
  const double elapsed = seconds_between(start_, now);
  char text[64];
  std::snprintf(text, sizeof text, ", %.0f s", elapsed);
  std::string line = label_ + ": " + item_ + " " + std::to_string(done_) + "/" + std::to_string(total_) + text;
  if (done_ > 0 && done_ < total_) {
    const double left = elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
    std::snprintf(text, sizeof text, ", about %.0f s left", left);
    line += text;
  }
  return line;
}

}  // namespace growthuq
