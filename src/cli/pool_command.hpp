// What the commands that run a campaign through the evaluation pool (`growthuq run`,
// `growthuq tradeoff`) share: running on every process of the pool, serially or under mpirun,
// and every process parsing the same campaign text.
#pragma once

#include <functional>
#include <string>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq::cli {

// Makes the pool and runs `command` with it. Every process meets the same errors at the same
// point (on_coordinator shares the coordinator's); the coordinator's reach main(), which
// reports them; the other processes only return main's exit code for them (2 for bad input,
// 3 for any other error). A process started in parallel that cannot join the others stops
// before anything is written (pool/launch.hpp), reported by the launcher's first process only.
int run_on_pool(const std::function<int(Pool&)>& command);

// The campaign file at `path`, read by the coordinator and broadcast, so that every process
// validates exactly the same text.
Campaign read_campaign_on_pool(const std::string& path, Pool& pool);

}  // namespace growthuq::cli
