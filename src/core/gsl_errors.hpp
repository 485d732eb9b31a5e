// GSL's default error handler aborts the process. The engine checks every GSL status itself,
// so the handler is switched off once, before the first GSL call of any component.
#pragma once

namespace growthuq::detail {

// Switches GSL's abort-on-error handler off; thread-safe (function-local static) and cheap
// after the first call.
void gsl_errors_return() noexcept;

}  // namespace growthuq::detail
