// SCAFFOLD: replaced by the component that implements 'growthuq relax'.
#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

int run_relax(const Arguments&) { throw InputError("growthuq relax", "not built yet"); }

}  // namespace growthuq::cli
