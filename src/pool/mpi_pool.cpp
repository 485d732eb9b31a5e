// The MPI pool: the only file of the engine that includes mpi.h.
//
// Protocol (dynamic master/worker where the master also works): rank 0 keeps up to two
// chunks assigned to every other rank, so a worker never idles waiting for the next one, and
// computes chunks itself between serving messages. A worker answers each ASSIGN with a RESULT
// (chunk index + values) or a FAILURE (chunk index + reason). When everything is sunk, or after
// the first failure, rank 0 sends STOP to every worker and drains messages until each worker
// has said DONE, so no send is left pending (no hang at exit). A stop request (Pool::stop_when,
// polled on rank 0 only) ends the handing out: rank 0 waits for the chunks in flight, sinks
// them, and stops the workers the same way. Finally rank 0 broadcasts the outcome ("" done,
// "F<reason>" failed, "S<request>" stopped) and every rank returns or throws the same.
#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <deque>
#include <string>

#include "growthuq/pool/pool.hpp"

namespace growthuq {
namespace {

enum Tag : int { assign_tag = 1, result_tag = 2, failure_tag = 3, stop_tag = 4, done_tag = 5 };

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
    if (!initialized) {
      MPI_Init(nullptr, nullptr);
      std::atexit(finalize_mpi);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void run(std::size_t count, std::size_t chunk_size, const ChunkWork& work, const ChunkSink& sink,
           const std::function<bool(ChunkRange)>& skip) override {
    const std::vector<ChunkRange> all = split_into_chunks(count, chunk_size);
    std::vector<std::uint64_t> todo;
    for (std::uint64_t i = 0; i < all.size(); ++i) {
      if (!skip || !skip(all[i])) todo.push_back(i);
    }
    const std::string outcome = broadcast(rank_ == 0 ? coordinate(all, todo, work, sink) : serve(all, work));
    if (outcome.empty()) return;
    if (outcome.front() == 'S') throw PoolInterrupted(std::stoi(outcome.substr(1)));
    throw PoolError(outcome.substr(1));
  }

  std::string broadcast(const std::string& text) override {
    std::uint64_t length = text.size();
    MPI_Bcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    std::string received = rank_ == 0 ? text : std::string(length, '\0');
    MPI_Bcast(received.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
    return received;
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
        if (failure.empty()) failure = "rank 0 could not keep items [" + std::to_string(range.begin) + ", " + std::to_string(range.end) + "): " + error.what();
      }
    };
    for (int round = 0; round < 2; ++round) {
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
      } else if (more) {
        const ChunkRange range = all[todo[next++]];
        std::vector<double> values;
        try {
          values = work(range);
        } catch (const std::exception& error) {
          failure = describe_failure(0, range, error.what());
        }
        if (failure.empty()) sink_safely(range, values);
        ++sunk;
      } else {
        MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        handle_message(status);
      }
    }

    // Stop every worker and drain what is still in flight until each has said DONE.
    for (int worker = 1; worker < size_; ++worker) MPI_Send(nullptr, 0, MPI_CHAR, worker, stop_tag, MPI_COMM_WORLD);
    for (int done = 0; done < size_ - 1;) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
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
  std::string serve(const std::vector<ChunkRange>& all, const ChunkWork& work) {
    for (;;) {
      MPI_Status status;
      MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
      if (status.MPI_TAG == stop_tag) {
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
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_DOUBLE, 0, result_tag, MPI_COMM_WORLD);
      } catch (const std::exception& error) {
        const std::string text = describe_failure(rank_, range, error.what());
        MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, failure_tag, MPI_COMM_WORLD);
      }
    }
  }

  int rank_ = 0;
  int size_ = 1;
};

}  // namespace

std::unique_ptr<Pool> make_mpi_pool() { return std::make_unique<MpiPool>(); }

}  // namespace growthuq
