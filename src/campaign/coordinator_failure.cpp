#include "campaign/coordinator_failure.hpp"

#include <stdexcept>

#include "growthuq/core/error.hpp"

namespace growthuq {

std::string FailureMessage::encode() const {
  return std::string(input_error ? "I" : "E") + location + '\0' + problem;
}

std::optional<FailureMessage> FailureMessage::decode(const std::string& message) {
  if (message.empty()) return std::nullopt;
  const std::size_t separator = message.find('\0');
  if (separator == std::string::npos) throw std::logic_error("failure message without separator");
  return FailureMessage{message[0] == 'I', message.substr(1, separator - 1), message.substr(separator + 1)};
}

void FailureMessage::raise() const {
  if (input_error) throw InputError(location, problem);
  throw std::runtime_error(problem);
}

void CoordinatorFailure::run(Pool& pool, const std::function<void()>& action) {
  if (!pool.is_coordinator() || failure_) return;
  try {
    action();
  } catch (const InputError& error) {
    message_ = FailureMessage{true, error.location(), error.problem()}.encode();
    failure_ = std::current_exception();
  } catch (const std::exception& error) {
    message_ = FailureMessage{false, "", error.what()}.encode();
    failure_ = std::current_exception();
  }
}

void CoordinatorFailure::share(Pool& pool) {
  const std::string message = pool.broadcast(message_);
  if (failure_) std::rethrow_exception(failure_);
  if (const std::optional<FailureMessage> failure = FailureMessage::decode(message)) failure->raise();
}

}  // namespace growthuq
