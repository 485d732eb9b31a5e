// SCAFFOLD: replaced by the component that implements 'growthuq correlate'.
#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

int run_correlate(const Arguments&) { throw InputError("growthuq correlate", "not built yet"); }

}  // namespace growthuq::cli
