// The MPI pool: the only file of the engine that includes mpi.h.
//
// Protocol (dynamic master/worker where the master also works): rank 0 keeps up to three
// chunks assigned to every other rank and computes chunks itself on a thread of its own, while
// its main thread, the only one that calls MPI (MPI_THREAD_FUNNELED), answers the workers: a
// worker gets its next chunk as soon as it returns one, however long rank 0's own chunk takes
// (a finite-element sample takes seconds to minutes). A worker answers each ASSIGN with a RESULT
// (chunk index + values) or a FAILURE (chunk index + reason). When everything is sunk, or after
// the first failure, rank 0 sends STOP to every worker and drains messages until each worker
// has said DONE, so no send is left pending (no hang at exit). A stop request (Pool::stop_when,
// polled on rank 0 only) ends the handing out: rank 0 waits for the chunks in flight, sinks
// them, and stops the workers the same way. Finally rank 0 broadcasts the outcome ("" done,
// "F<reason>" failed, "S<request>" stopped) and every rank returns or throws the same.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <exception>
#include <future>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "growthuq/pool/pool.hpp"

namespace growthuq {
namespace {


enum Tag : int { assign_tag = 1, result_tag = 2, failure_tag = 3, stop_tag = 4, done_tag = 5, gather_tag = 6 };

// Waiting without spinning a core: MPI's own blocking calls poll flat out, which on a machine
// with as many processes as cores takes the core from anything else that could run there (the
// coordinator's writer thread, other programs). These poll, then sleep a little longer each time
// (10 us doubling to 200 us: a message then waits at most that much more than it would).
void pause_between_polls(long& microseconds) {
  std::this_thread::sleep_for(std::chrono::microseconds(microseconds));
  microseconds = std::min(2 * microseconds, 200L);
}

void wait_gently(MPI_Request& request) {
  int done = 0;
  MPI_Test(&request, &done, MPI_STATUS_IGNORE);
  for (long pause = 10; !done; MPI_Test(&request, &done, MPI_STATUS_IGNORE)) pause_between_polls(pause);
}

void probe_gently(int source, MPI_Status& status) {
  int pending = 0;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status);
  for (long pause = 10; !pending; MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status)) {
    pause_between_polls(pause);
  }
}

// A broadcast whose receivers wait gently for the root, then move the data at full speed: a
// large broadcast goes in segments, each needing both sides to poll, which sleeping between
// polls would slow tenfold.
void broadcast_gently(void* data, int count, MPI_Datatype type, int root) {
  char ready = 1;
  MPI_Request request;
  MPI_Ibcast(&ready, 1, MPI_CHAR, root, MPI_COMM_WORLD, &request);
  wait_gently(request);
  MPI_Bcast(data, count, type, root, MPI_COMM_WORLD);
}

void finalize_mpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

std::string describe_failure(int rank, ChunkRange range, const std::string& reason) {
  return "rank " + std::to_string(rank) + " failed on items [" + std::to_string(range.begin) + ", " +
         std::to_string(range.end) + "): " + reason;
}

class MpiPool final : public Pool {
 public:
  MpiPool() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    int threads = MPI_THREAD_SINGLE;
    if (!initialized) {
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &threads);
      std::atexit(finalize_mpi);
    } else {
      MPI_Query_thread(&threads);
    }
    // Without it, rank 0 computes its chunks on its main thread, between messages.
    compute_aside_ = threads >= MPI_THREAD_FUNNELED;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // The processes that can share memory with this one: those on its machine.
    MPI_Comm local;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &local);
    MPI_Comm_size(local, &local_size_);
    MPI_Comm_free(&local);
  }

  ~MpiPool() override {
    // Rank 0 takes every gather's numbers in the normal course of a run; after a failure it may
    // not have, and waiting would hang: what is still pending is let go.
    forget_sent();
    for (Sent& sent : sent_) {
      for (MPI_Request& request : sent.requests) {
        if (request != MPI_REQUEST_NULL) MPI_Request_free(&request);
      }
    }
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  int processes_on_this_machine() const override { return local_size_; }

  void run(std::size_t count, std::size_t chunk_size, const ChunkWork& work, const ChunkSink& sink,
           const std::function<bool(ChunkRange)>& skip) override {
    const std::vector<ChunkRange> all = split_into_chunks(count, chunk_size);
    std::vector<std::uint64_t> todo;
    for (std::uint64_t i = 0; i < all.size(); ++i) {
      if (!skip || !skip(all[i])) todo.push_back(i);
    }
    sink_failure_ = nullptr;
    const std::string outcome = broadcast(rank_ == 0 ? coordinate(all, todo, work, sink) : serve(all, work));
    if (outcome.empty()) return;
    if (outcome.front() == 'S') throw PoolInterrupted(std::stoi(outcome.substr(1)));
    // The sink's own exception on rank 0, as the serial pool lets it through (a checkpoint that
    // could not be written is a WriteError there, which keeps the checkpoint for a resume).
    if (sink_failure_) std::rethrow_exception(std::exchange(sink_failure_, nullptr));
    throw PoolError(outcome.substr(1));
  }

  std::string broadcast(const std::string& text) override {
    std::uint64_t length = text.size();
    broadcast_gently(&length, 1, MPI_UINT64_T, 0);
    std::string received = rank_ == 0 ? text : std::string(length, '\0');
    broadcast_gently(received.data(), static_cast<int>(length), MPI_CHAR, 0);
    return received;
  }

  std::vector<std::vector<double>> gather(std::vector<double> values) override {
    // Sizes first, then the numbers in pieces (MPI counts are ints), rank by rank.
    constexpr std::size_t piece = std::size_t{1} << 27;  // doubles: 1 GiB
    std::vector<std::vector<double>> all;
    // A sender does not wait: its numbers go out in the background (kept here until rank 0 has
    // taken them), so that it can go on while rank 0 is busy. Rank 0 waits gently for each
    // sender's size, then receives at full speed.
    forget_sent();
    if (rank_ != 0) {
      Sent& sent = sent_.emplace_back();
      sent.size = values.size();
      sent.values = std::move(values);
      sent.requests.emplace_back();
      MPI_Isend(&sent.size, 1, MPI_UINT64_T, 0, gather_tag, MPI_COMM_WORLD, &sent.requests.back());
      for (std::size_t done = 0; done < sent.values.size(); done += piece) {
        sent.requests.emplace_back();
        MPI_Isend(sent.values.data() + done, static_cast<int>(std::min(piece, sent.values.size() - done)), MPI_DOUBLE, 0,
                  gather_tag, MPI_COMM_WORLD, &sent.requests.back());
      }
      return all;
    }
    all.push_back(std::move(values));
    for (int source = 1; source < size_; ++source) {
      MPI_Status status;
      probe_gently(source, status);
      std::uint64_t size = 0;
      MPI_Recv(&size, 1, MPI_UINT64_T, source, gather_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      std::vector<double>& received = all.emplace_back(size);
      for (std::size_t done = 0; done < received.size(); done += piece) {
        MPI_Recv(received.data() + done, static_cast<int>(std::min(piece, received.size() - done)), MPI_DOUBLE, source,
                 gather_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      }
    }
    return all;
  }

  void broadcast_bytes(std::span<std::byte> data, int root) override {
    // MPI counts are ints: pieces of at most 1 GiB.
    constexpr std::size_t piece = std::size_t{1} << 30;
    for (std::size_t done = 0; done < data.size(); done += piece) {
      const std::size_t size = std::min(piece, data.size() - done);
      broadcast_gently(data.data() + done, static_cast<int>(size), MPI_BYTE, root);
    }
  }

 private:
  // Rank 0: hands out chunks, computes chunks itself, sinks results. Returns the outcome.
  std::string coordinate(const std::vector<ChunkRange>& all, const std::vector<std::uint64_t>& todo,
                         const ChunkWork& work, const ChunkSink& sink) {
    std::size_t next = 0;  // chunks handed out (to workers or to rank 0 itself)
    std::size_t sunk = 0;  // chunks back (sunk or failed)
    std::string failure;
    int stop = stop_requested();
    auto handing_out = [&] { return failure.empty() && stop == 0 && next < todo.size(); };
    auto assign_next = [&](int worker) {
      if (!handing_out()) return;
      MPI_Send(&todo[next], 1, MPI_UINT64_T, worker, assign_tag, MPI_COMM_WORLD);
      ++next;
    };
    // A sink that throws (the checkpoint cannot be written) fails the run like a chunk does;
    // escaping here would leave the workers waiting.
    auto sink_safely = [&](ChunkRange range, std::span<const double> values) {
      try {
        sink(range, values);
      } catch (const std::exception& error) {
        if (failure.empty()) {
          failure = "rank 0 could not keep items [" + std::to_string(range.begin) + ", " + std::to_string(range.end) + "): " + error.what();
          sink_failure_ = std::current_exception();
        }
      }
    };
    // Chunks kept assigned to each worker (Pool::queued_chunks): enough that a worker still has
    // work while rank 0 is busy with a chunk of its own.
    for (int round = 0; round < queued_chunks(); ++round) {
      for (int worker = 1; worker < size_; ++worker) assign_next(worker);
    }

    std::vector<double> buffer;
    auto handle_message = [&](const MPI_Status& status) {
      int length = 0;
      if (status.MPI_TAG == result_tag) {
        MPI_Get_count(&status, MPI_DOUBLE, &length);
        buffer.resize(static_cast<std::size_t>(length));
        MPI_Recv(buffer.data(), length, MPI_DOUBLE, status.MPI_SOURCE, result_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const auto index = static_cast<std::size_t>(buffer.front());
        if (failure.empty()) sink_safely(all[index], std::span<const double>(buffer).subspan(1));
        ++sunk;
        assign_next(status.MPI_SOURCE);
      } else if (status.MPI_TAG == failure_tag) {
        MPI_Get_count(&status, MPI_CHAR, &length);
        std::string text(static_cast<std::size_t>(length), '\0');
        MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, failure_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (failure.empty()) failure = text;
        ++sunk;
      }
    };

    // Rank 0's own chunk, computed on a thread of its own while this one serves the workers.
    std::optional<ChunkRange> own;
    std::future<std::vector<double>> own_values;
    const auto finish_own = [&] {
      std::vector<double> values;
      try {
        values = own_values.get();
      } catch (const std::exception& error) {
        if (failure.empty()) failure = describe_failure(0, *own, error.what());
      }
      if (failure.empty()) sink_safely(*own, values);
      ++sunk;
      own.reset();
    };
    long pause = 10;
    for (;;) {
      if (stop == 0) stop = stop_requested();
      // Decided once per pass: blocking below is safe only while chunks are in flight.
      const bool more = handing_out();
      if (!failure.empty() || (!more && sunk == next)) break;
      int pending = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status);
      if (pending) {
        handle_message(status);
        pause = 10;
      } else if (own && own_values.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        finish_own();
        pause = 10;
      } else if (more && !own) {
        own = all[todo[next++]];
        if (compute_aside_) {
          own_values = std::async(std::launch::async, [&work, range = *own] { return work(range); });
        } else {
          std::promise<std::vector<double>> computed;
          try {
            computed.set_value(work(*own));
          } catch (...) {
            computed.set_exception(std::current_exception());
          }
          own_values = computed.get_future();
        }
      } else if (own) {
        pause_between_polls(pause);  // rank 0's chunk is still being computed
      } else {
        probe_gently(MPI_ANY_SOURCE, status);
        handle_message(status);
      }
    }
    // After a failure rank 0's own chunk may still be under way: it ends before the workers stop.
    if (own) finish_own();

    // Stop every worker and drain what is still in flight until each has said DONE.
    for (int worker = 1; worker < size_; ++worker) MPI_Send(nullptr, 0, MPI_CHAR, worker, stop_tag, MPI_COMM_WORLD);
    for (int done = 0; done < size_ - 1;) {
      MPI_Status status;
      probe_gently(MPI_ANY_SOURCE, status);
      if (status.MPI_TAG == done_tag) {
        MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, done_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        ++done;
      } else {
        handle_message(status);
      }
    }
    if (!failure.empty()) return "F" + failure;
    return stop != 0 && sunk < todo.size() ? "S" + std::to_string(stop) : std::string();
  }

  // Ranks > 0: compute assigned chunks until STOP. Returns "" (rank 0 reports failures).
  // Results go out without waiting (MPI_Isend): a large message is only copied when rank 0
  // receives it, between chunks of its own, and the next queued chunk is computed meanwhile.
  std::string serve(const std::vector<ChunkRange>& all, const ChunkWork& work) {
    struct Sending {
      MPI_Request request;
      std::vector<double> message;
    };
    std::deque<Sending> sending;  // a deque never moves its elements: buffers stay put
    const auto complete_sent = [&](bool wait) {
      while (!sending.empty()) {
        int done = 0;
        if (wait) {
          MPI_Wait(&sending.front().request, MPI_STATUS_IGNORE);
          done = 1;
        } else {
          MPI_Test(&sending.front().request, &done, MPI_STATUS_IGNORE);
        }
        if (!done) return;
        sending.pop_front();
      }
    };
    for (;;) {
      MPI_Status status;
      probe_gently(0, status);
      if (status.MPI_TAG == stop_tag) {
        complete_sent(true);
        MPI_Recv(nullptr, 0, MPI_CHAR, 0, stop_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(nullptr, 0, MPI_CHAR, 0, done_tag, MPI_COMM_WORLD);
        return {};
      }
      std::uint64_t index = 0;
      MPI_Recv(&index, 1, MPI_UINT64_T, 0, assign_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const ChunkRange range = all[index];
      try {
        std::vector<double> message = work(range);
        message.insert(message.begin(), static_cast<double>(index));
        Sending& out = sending.emplace_back();
        out.message = std::move(message);
        MPI_Isend(out.message.data(), static_cast<int>(out.message.size()), MPI_DOUBLE, 0, result_tag, MPI_COMM_WORLD,
                  &out.request);
        complete_sent(false);
      } catch (const std::exception& error) {
        const std::string text = describe_failure(rank_, range, error.what());
        MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, failure_tag, MPI_COMM_WORLD);
      }
    }
  }

  // Numbers a gather sent and rank 0 may not have taken yet (their buffers must live until then).
  struct Sent {
    std::uint64_t size = 0;
    std::vector<double> values;
    std::vector<MPI_Request> requests;
  };

  // Drops what rank 0 has taken.
  void forget_sent() {
    while (!sent_.empty()) {
      int done = 0;
      MPI_Testall(static_cast<int>(sent_.front().requests.size()), sent_.front().requests.data(), &done,
                  MPI_STATUSES_IGNORE);
      if (!done) return;
      sent_.pop_front();
    }
  }

  std::exception_ptr sink_failure_;  // rank 0: what the sink threw in the current run()
  bool compute_aside_ = false;       // rank 0 computes its chunks on a thread of its own
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
  std::deque<Sent> sent_;  // a deque never moves its elements: the buffers stay put
};

}  // namespace

std::unique_ptr<Pool> make_mpi_pool() { return std::make_unique<MpiPool>(); }

}  // namespace growthuq
