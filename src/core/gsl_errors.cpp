#include "core/gsl_errors.hpp"

#include <gsl/gsl_errno.h>

namespace growthuq::detail {

void gsl_errors_return() noexcept {
  static const bool switched_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)switched_off;
}

}  // namespace growthuq::detail
