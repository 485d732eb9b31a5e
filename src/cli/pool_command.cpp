#include "pool_command.hpp"

#include <exception>
#include <memory>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/pool/launch.hpp"

namespace growthuq::cli {

int run_on_pool(const std::function<int(Pool&)>& command) {
  std::unique_ptr<Pool> pool;
  try {
    pool = make_pool();
  } catch (const UnjoinableLaunch& error) {
    // Every process of the launch finds the same: the first reports it, for one message.
    if (error.launcher_rank() != 0) return 2;
    throw;
  }
  if (pool->is_coordinator()) return command(*pool);
  try {
    return command(*pool);
  } catch (const InputError&) {
    return 2;
  } catch (const std::exception&) {
    return 3;
  }
}

Campaign read_campaign_on_pool(const std::string& path, Pool& pool) {
  std::string text;
  on_coordinator(pool, [&] { text = read_campaign(path).text; });
  text = pool.broadcast(text);
  return parse_campaign(text, path);
}

}  // namespace growthuq::cli
