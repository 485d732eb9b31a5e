// SCAFFOLD: replaced by the component that implements 'growthuq eval'.
#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

int run_eval(const Arguments&) { throw InputError("growthuq eval", "not built yet"); }

}  // namespace growthuq::cli
