// SCAFFOLD: replaced by the component that implements 'growthuq fit'.
#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

int run_fit(const Arguments&) { throw InputError("growthuq fit", "not built yet"); }

}  // namespace growthuq::cli
