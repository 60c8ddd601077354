#pragma once
// A thin, copyable handle to an MPI communicator with the few collectives the modules use.
#include <mpi.h>

#include <string>
#include <vector>

namespace picdem::core {

class Comm {
 public:
  Comm() : comm_(MPI_COMM_WORLD) {}
  explicit Comm(MPI_Comm comm) : comm_(comm) {}

  MPI_Comm raw() const { return comm_; }
  int rank() const;
  int size() const;
  bool is_root() const { return rank() == 0; }
  void barrier() const;

  double sum(double v) const;
  long long sum(long long v) const;
  double max(double v) const;
  double min(double v) const;
  long long max(long long v) const;
  long long min(long long v) const;
  /// Logical OR over all ranks.
  bool any(bool v) const;
  /// Exclusive prefix sum over ranks (rank 0 gets 0).
  long long exclusive_scan(long long v) const;
  /// Element-wise sums, in place.
  void sum_in_place(std::vector<double>& v) const;
  void sum_in_place(std::vector<long long>& v) const;
  /// Rank `root`'s string on every rank.
  std::string broadcast(const std::string& s, int root = 0) const;
  /// A failure found on one rank stops every rank, never just one: when any rank's `failure` is
  /// not empty, throws core::SolverError on every rank: with its own message, or on a rank
  /// without one, the lowest failing rank's.
  void throw_if_any(const std::string& failure) const;
  /// Concatenation of every rank's doubles in rank order, on every rank.
  std::vector<double> all_gather(const std::vector<double>& mine) const;

 private:
  MPI_Comm comm_;
};

}  // namespace picdem::core
