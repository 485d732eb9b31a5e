// What the coordinator's work threw, kept and raised on every process when they next meet, so
// that the coordinator's work after a line (handing it to the writers) holds nobody up and a
// failure still stops every process at the same point. on_coordinator (campaign_run.hpp) is
// the one-step use.
#pragma once

#include <exception>
#include <functional>
#include <optional>
#include <string>

#include "growthuq/pool/pool.hpp"

namespace growthuq {

// A failure as it travels to the other processes: an InputError (location and problem) or any
// other exception (its what() as the problem, no location).
struct FailureMessage {
  bool input_error = false;
  std::string location;
  std::string problem;

  // Text: kind ('I' InputError, 'E' other), location, NUL, problem. decode(encode()) gives the
  // same fields (a location holds no NUL); decode("") is nullopt (no failure).
  std::string encode() const;
  static std::optional<FailureMessage> decode(const std::string& message);

  // Throws it: InputError(location, problem) or std::runtime_error(problem).
  [[noreturn]] void raise() const;
};

class CoordinatorFailure {
 public:
  // On the coordinator: action(), unless an earlier action failed; what it throws is kept.
  // Elsewhere nothing.
  void run(Pool& pool, const std::function<void()>& action);

  // Every process: raises the kept failure everywhere (on the coordinator the original
  // exception, elsewhere FailureMessage::raise).
  void share(Pool& pool);

 private:
  std::string message_;
  std::exception_ptr failure_;
};

}  // namespace growthuq
