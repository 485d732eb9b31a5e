// SCAFFOLD: replaced by the component that implements 'growthuq sample'.
#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

int run_sample(const Arguments&) { throw InputError("growthuq sample", "not built yet"); }

}  // namespace growthuq::cli
