// The readable side of the trade: what `growthuq tradeoff` prints on stdout (per-fidelity
// verdicts, then the runs against the finite-element reference).
#include "growthuq/campaign/tradeoff.hpp"
#include "growthuq/campaign/tradeoff_choice.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "campaign/tradeoff_worst.hpp"

namespace growthuq {
namespace {

std::string significant(double value, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string seconds_text(double seconds) { return significant(seconds, 3) + " s"; }

std::string where(const TradeoffWorst& worst) { return worst.line + " " + worst.quantity; }

// "8.12 % (pme48 eta)"; "undefined (pme48 v)" for NaN. Three digits, so that an error just
// above a round target (1.02 %) does not print as the target itself.
std::string worst_cell(const TradeoffWorst& worst, const char* unit) {
  const std::string value = std::isnan(worst.value) ? "undefined" : significant(worst.value, 3) + unit;
  return value + " (" + where(worst) + ")";
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

std::string right_aligned(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

// Breaks a paragraph into lines of at most `width` characters at spaces.
std::string wrapped(const std::string& paragraph, std::size_t width = 96) {
  std::string text;
  std::string line;
  std::size_t start = 0;
  while (start < paragraph.size()) {
    std::size_t end = paragraph.find(' ', start);
    if (end == std::string::npos) end = paragraph.size();
    const std::string word = paragraph.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      text += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  if (!line.empty()) text += line + "\n";
  return text;
}

std::string target_answer(const TradeoffVerdict& v) {
  const std::string target = significant(v.target_pct, 3) + " %";
  const std::string reference = std::to_string(v.reference_samples);
  if (v.smallest_meeting_target) {
    double seconds = 0;
    for (const TradeoffCount& count : v.counts) {
      if (count.samples == *v.smallest_meeting_target) seconds = count.seconds;
    }
    return "target " + target + ": " + std::to_string(*v.smallest_meeting_target) +
           " samples per line. From this count on, the median and IQR of every line and quantity are within " + target +
           " of the " + reference + "-sample reference (" + seconds_text(seconds) + " per campaign instead of " +
           seconds_text(v.counts.back().seconds) + ").";
  }
  const TradeoffCount& last = v.counts[v.counts.size() - 2];
  std::string text = "target " + target + ": no sample count below the reference meets it. The largest error left at " +
                     std::to_string(last.samples) + " samples per line is ";
  if (std::isnan(v.remaining_error_pct.value)) {
    return text + "undefined (" + v.remaining_statistic + " of " + where(v.remaining_error_pct) +
           ": the reference is 0 or no sample counts in it), so no count can be shown to meet a relative target.";
  }
  text += significant(v.remaining_error_pct.value, 3) + " % (" + v.remaining_statistic + " of " +
          where(v.remaining_error_pct) + ").";
  if (v.estimated_samples_needed > 0) {
    text += " If errors fall like 1/sqrt(n), about " + std::to_string(v.estimated_samples_needed) +
            " samples per line would meet it: extend --samples-list beyond that, with a reference several times larger.";
  }
  return text;
}

std::string reference_precision(const TradeoffVerdict& v) {
  const TradeoffWorst& worst = v.reference_ci_half_width_pct;
  const std::string target = significant(v.target_pct, 3) + " %";
  if (std::isnan(worst.value)) {
    return "Caution: the reference run's 95 % confidence interval of the median is undefined for " + where(worst) +
           " (a median of 0, or 5 or fewer samples that count), so its own precision is unknown there.";
  }
  const std::string half_width = "+-" + significant(worst.value, 2) + " % of the median (" + where(worst) + ")";
  if (v.reference_precise_enough) {
    return "The reference run's own 95 % confidence interval of the median is at most " + half_width +
           ", well below the target: the errors above are those of the smaller runs.";
  }
  return "Caution: the reference run's own 95 % confidence interval of the median reaches " + half_width +
         ", not well below the " + target + " target (at most a quarter of it would be): the errors above partly" +
         " measure the reference's own noise. Add a larger count to --samples-list.";
}

// "closed_form at 20 samples per line (0.0012 s per campaign)"
std::string run_name(const TradeoffRunAgainstFe& run) {
  return run.fidelity + " at " + std::to_string(run.samples) + " samples per line (" + seconds_text(run.seconds) +
         " per campaign)";
}

std::string choice_answer(const TradeoffChoice& c) {
  const std::string target = significant(c.target_pct, 3) + " %";
  const std::string reference = "the " + std::to_string(c.reference_samples) + "-sample shell_fe reference";
  std::string text = "against " + reference + ", target " + target + ": ";
  if (c.cheapest) {
    return text + "the cheapest run is " + run_name(c.runs[*c.cheapest]) + ": its median and IQR of every line and " +
           "quantity are within " + target + " of the finite-element model's.";
  }
  if (!c.closest) return text + "no run besides the reference to compare (add a fidelity to --fidelities).";
  const TradeoffRunAgainstFe& closest = c.runs[*c.closest];
  const bool iqr_worse = worse_error(closest.iqr_error_pct.value, closest.median_error_pct.value);
  const TradeoffWorst& worst = iqr_worse ? closest.iqr_error_pct : closest.median_error_pct;
  const std::string value = std::isnan(worst.value) ? "undefined" : significant(worst.value, 3) + " %";
  return text + "no run has every median and IQR within it. Closest is " + run_name(closest) +
         ", whose largest error is " + value + " (" + (iqr_worse ? "IQR" : "median") + " of " + where(worst) + ").";
}

}  // namespace

std::string format_tradeoff_choice(const TradeoffChoice& choice) {
  constexpr std::size_t fidelity_width = 13, count_width = 12, seconds_width = 10, error_width = 31;
  std::string text = padded("fidelity", fidelity_width) + right_aligned("samples/line", count_width) +
                     right_aligned("seconds", seconds_width) + "   " + padded("worst median error vs FE", error_width) +
                     "worst IQR error vs FE\n";
  for (const TradeoffRunAgainstFe& run : choice.runs) {
    text += padded(run.fidelity, fidelity_width) + right_aligned(std::to_string(run.samples), count_width) +
            right_aligned(significant(run.seconds, 3), seconds_width) + "   ";
    if (run.is_reference) {
      text += padded("reference", error_width) + "reference\n";
      continue;
    }
    text += padded(worst_cell(run.median_error_pct, " %"), error_width) + worst_cell(run.iqr_error_pct, " %") + "\n";
  }
  return text + "\n" + wrapped(choice_answer(choice));
}

std::string format_tradeoff_report(const TradeoffVerdict& verdict) {
  constexpr std::size_t count_width = 12, seconds_width = 10, error_width = 31;
  std::string text = right_aligned("samples/line", count_width) + right_aligned("seconds", seconds_width) + "   " +
                     padded("worst median error", error_width) + padded("worst IQR error", error_width) +
                     "worst |error| / CI half-width\n";
  for (const TradeoffCount& count : verdict.counts) {
    text += right_aligned(std::to_string(count.samples), count_width) +
            right_aligned(significant(count.seconds, 3), seconds_width) + "   ";
    if (count.samples == verdict.reference_samples) {
      text += padded("reference", error_width) + padded("reference", error_width) + "reference\n";
      continue;
    }
    text += padded(worst_cell(count.median_error_pct, " %"), error_width) +
            padded(worst_cell(count.iqr_error_pct, " %"), error_width) +
            worst_cell(count.median_error_over_ci_half_width, "") + "\n";
  }
  text += "\n" + wrapped(target_answer(verdict)) + wrapped(reference_precision(verdict));
  return text;
}

}  // namespace growthuq
