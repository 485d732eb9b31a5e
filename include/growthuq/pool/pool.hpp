// Where evaluation runs, behind one small interface (the "batch evaluator" idea of pagmo2):
// a Pool cuts a task of `count` items into fixed chunks, has workers compute them, and hands
// every finished chunk to a sink on the coordinating process. Numerical code sees only this
// header; MPI lives in src/pool/mpi_pool.cpp alone.
//
// Results do not depend on the number of processes: chunk boundaries depend only on `count`
// and `chunk_size`, and a chunk's content only on its range (the work function must be a pure
// function of [begin, end)). Chunks reach the sink in any order; the sink places them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace growthuq {

// A half-open range of items [begin, end).
struct ChunkRange {
  std::size_t begin = 0;
  std::size_t end = 0;
};

// Computes the items of `range` and returns them serialized as doubles (the work function
// decides the layout; the sink reads it back). May throw: the pool stops the whole run and
// reports the rank, the range and the reason.
using ChunkWork = std::function<std::vector<double>(ChunkRange range)>;

// Receives a finished chunk on the coordinating process (rank 0).
using ChunkSink = std::function<void(ChunkRange range, std::span<const double> values)>;

// Thrown on every process when a chunk failed somewhere; what() names rank, range and reason.
class PoolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown on every process when run() stopped early because the coordinator's stop request
// (Pool::stop_when) returned `reason` (nonzero; the CLI uses the signal number). Every chunk
// handed out before the stop was finished and sunk.
class PoolInterrupted : public std::runtime_error {
 public:
  explicit PoolInterrupted(int reason)
      : std::runtime_error("stopped on request " + std::to_string(reason)), reason_(reason) {}
  int reason() const noexcept { return reason_; }

 private:
  int reason_;
};

class Pool {
 public:
  virtual ~Pool() = default;

  // This process's number (0 coordinates) and the number of processes.
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool is_coordinator() const { return rank() == 0; }
  // How many of the processes share this process's machine (and its memory).
  virtual int processes_on_this_machine() const = 0;

  // Runs `work` over [0, count) in chunks of `chunk_size`, handed out dynamically so that
  // slow chunks balance; `skip(range)` (optional) tells chunks already done (resume). Every
  // process must call run() with the same count, chunk_size and skip; `sink` is called only
  // on rank 0. Returns when every chunk has been sunk; throws PoolError if a chunk failed (what
  // the sink threw, on rank 0 the exception itself, elsewhere a PoolError).
  virtual void run(std::size_t count, std::size_t chunk_size, const ChunkWork& work,
                   const ChunkSink& sink,
                   const std::function<bool(ChunkRange)>& skip = nullptr) = 0;

  // Lets run() stop early (Ctrl-C, SIGTERM): the coordinator calls `request` before handing out
  // each chunk; a nonzero value means no new chunk starts, chunks under way finish and reach
  // the sink, and run() throws PoolInterrupted(value) on every process. Only the coordinator's
  // request counts: under mpirun every rank may see the signal, and the coordinator decides
  // for all of them, so they stop at the same point and nothing waits for a rank that left.
  void stop_when(std::function<int()> request) { stop_request_ = std::move(request); }

  // Chunks assigned to each worker at a time, the one it computes included (the MPI pool; 3 by
  // default): a queue hides the round trip of a result and its next assignment behind a chunk of
  // milliseconds; chunks of seconds or minutes (finite-element samples) want none (1), since a
  // queued chunk can no longer go to whichever process frees up first. Rank 0 computes chunks too,
  // on a thread of its own, and answers workers meanwhile. Every process sets the same value.
  void set_queued_chunks(int chunks) { queued_chunks_ = chunks < 1 ? 1 : chunks; }
  int queued_chunks() const { return queued_chunks_; }

  // Sends `text` from rank 0 to every process (campaign text, so all ranks validate the same
  // input); returns it on every rank.
  virtual std::string broadcast(const std::string& text) = 0;

  // Copies `data` of process `root` into `data` of every other process (work one process did
  // that all need, such as a design column). Every process calls it with the same root and
  // size. Serially, root must be 0 and nothing happens.
  virtual void broadcast_bytes(std::span<std::byte> data, int root) = 0;

  // Collects what every process contributes on the coordinator: rank 0 gets all contributions
  // in rank order (its own first), the others an empty vector at once (their numbers go out in
  // the background, so that they need not wait for rank 0). Every process calls it, the same
  // number of times in the same order, but not necessarily at the same moment. For work shared
  // out in advance (each process knows its part), where the dynamic run() would make the
  // coordinator both compute and serve.
  virtual std::vector<std::vector<double>> gather(std::vector<double> values) = 0;

  // broadcast_bytes for a contiguous vector of numbers, resized to `size` first.
  template <class Vector>
  void broadcast_vector(Vector& values, std::size_t size, int root) {
    values.resize(size);
    broadcast_bytes(std::as_writable_bytes(std::span(values.data(), size)), root);
  }

  // The stop request's value now (0: none); meaningful on the coordinator, whose request
  // decides. Also for work after run() (a campaign's final writes).
  int stop_requested() const { return stop_request_ ? stop_request_() : 0; }

 private:
  std::function<int()> stop_request_;
  int queued_chunks_ = 3;
};

// The chunks of [0, count), in order; the last may be shorter. chunk_size 0 is treated as 1.
std::vector<ChunkRange> split_into_chunks(std::size_t count, std::size_t chunk_size);

// Runs item(i) for every i < count over the pool, one item per chunk (items of uneven cost
// balance), and returns on the coordinator every item's numbers in order of i (an empty vector
// on the other processes); collected() is called on the coordinator after each item arrives.
std::vector<std::vector<double>> run_items(Pool& pool, std::size_t count,
                                           const std::function<std::vector<double>(std::size_t item)>& item,
                                           const std::function<void()>& collected);

// A pool of one process that runs chunks in order.
std::unique_ptr<Pool> make_serial_pool();

// True when this process was started in parallel: by mpirun, or as one of several tasks of srun
// (growthuq/pool/launch.hpp reads the environment).
bool launched_by_mpi();

// The MPI pool over MPI_COMM_WORLD; initializes MPI on first use and finalizes it at exit.
// Only call when launched_by_mpi().
std::unique_ptr<Pool> make_mpi_pool();

// The MPI pool when launched in parallel, else the serial pool. Throws UnjoinableLaunch
// (launch.hpp) when the process was started in parallel but cannot join the others.
std::unique_ptr<Pool> make_pool();

}  // namespace growthuq
