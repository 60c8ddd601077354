#pragma once
// Grid fields with a halo, indexed by global (i, k), and the two named communication verbs:
//   forward     : owners' values -> the ghost copies on other ranks,
//   reverse_add : ghost contributions -> added into the owners' values.
#include <mpi.h>

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "picdem/core/timer.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::grid {

/// A staggered quantity over this rank's storage box (owned + halo), row-major, i fastest.
template <class T>
class GridArray {
 public:
  GridArray() = default;
  GridArray(const Decomposition& d, Stagger s, T init = T{})
      : stagger_(s),
        owned_(d.owned(s)),
        box_(d.storage(s)),
        nxs_(box_.nx()),
        data_(static_cast<std::size_t>(box_.size()), init) {}

  T& operator()(int i, int k) { return data_[index(i, k)]; }
  const T& operator()(int i, int k) const { return data_[index(i, k)]; }
  std::size_t index(int i, int k) const {
    return static_cast<std::size_t>(k - box_.k0) * nxs_ + static_cast<std::size_t>(i - box_.i0);
  }
  bool in_storage(int i, int k) const { return box_.contains(i, k); }

  Stagger stagger() const { return stagger_; }
  const IndexBox& owned() const { return owned_; }
  const IndexBox& storage() const { return box_; }
  std::vector<T>& data() { return data_; }
  const std::vector<T>& data() const { return data_; }
  void fill(const T& v) { std::fill(data_.begin(), data_.end(), v); }

 private:
  Stagger stagger_ = Stagger::Cell;
  IndexBox owned_, box_;
  int nxs_ = 0;
  std::vector<T> data_;
};

using CellField = GridArray<double>;
using FaceField = GridArray<double>;

/// The pairwise overlaps between this rank's storage and the other ranks' owned samples,
/// computed once per staggering; then each exchange is one round of non-blocking messages.
class Halo {
 public:
  explicit Halo(const Decomposition& d);

  template <class T>
  void forward(GridArray<T>& f) const {
    exchange(f, /*reverse=*/false);
  }
  /// Adds every rank's ghost values into the owners' values. Ghost values are left as they
  /// were; call forward() to make them consistent again.
  template <class T>
  void reverse_add(GridArray<T>& f) const {
    exchange(f, /*reverse=*/true);
  }
  /// forward() of several arrays (any staggerings) in one round of messages: one message per
  /// neighbour carries all of them. The same values as one forward() per array.
  template <class T>
  void forward_all(std::initializer_list<GridArray<T>*> fs) const {
    exchange_all(fs, /*reverse=*/false);
  }
  /// reverse_add() of several arrays in one round of messages; every sample receives the same
  /// additions in the same (rank) order as with one reverse_add() per array.
  template <class T>
  void reverse_add_all(std::initializer_list<GridArray<T>*> fs) const {
    exchange_all(fs, /*reverse=*/true);
  }

 private:
  struct Link {
    int rank;
    IndexBox mine_in_theirs;  // my owned samples inside their storage
    IndexBox theirs_in_mine;  // their owned samples inside my storage
  };
  const std::vector<Link>& links(Stagger s) const { return links_[static_cast<int>(s)]; }

  template <class T>
  static void pack(const GridArray<T>& f, const IndexBox& b, std::vector<T>& buf) {
    buf.clear();
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i) buf.push_back(f(i, k));
  }

  template <class T>
  static void unpack(GridArray<T>& f, const IndexBox& b, const T* buf, bool reverse) {
    for (int k = b.k0; k < b.k1; ++k)
      for (int i = b.i0; i < b.i1; ++i, ++buf) {
        if (reverse)
          f(i, k) += *buf;
        else
          f(i, k) = *buf;
      }
  }

  /// The box of `f` sent to (out) or received from rank r: empty when r is not its neighbour.
  template <class T>
  IndexBox box_with(const GridArray<T>& f, int r, bool out, bool reverse) const {
    for (const Link& l : links(f.stagger()))
      if (l.rank == r) return out != reverse ? l.mine_in_theirs : l.theirs_in_mine;
    return IndexBox{};
  }

  template <class T>
  void exchange(GridArray<T>& f, bool reverse) const {
    const auto& ls = links(f.stagger());
    if (ls.empty()) return;
    core::ScopedTimer timer(reverse ? "halo: reverse add" : "halo: forward");
    std::vector<std::vector<T>> send(ls.size()), recv(ls.size());
    std::vector<MPI_Request> req;
    req.reserve(2 * ls.size());
    const int tag = 700 + static_cast<int>(f.stagger());
    for (std::size_t n = 0; n < ls.size(); ++n) {
      // forward: I send my owned values that sit in their halo; reverse: I send my ghosts of
      // their owned values.
      const IndexBox& out = reverse ? ls[n].theirs_in_mine : ls[n].mine_in_theirs;
      const IndexBox& in = reverse ? ls[n].mine_in_theirs : ls[n].theirs_in_mine;
      recv[n].resize(static_cast<std::size_t>(in.size()));
      req.emplace_back();
      MPI_Irecv(recv[n].data(), static_cast<int>(recv[n].size() * sizeof(T)), MPI_BYTE, ls[n].rank,
                tag, comm_, &req.back());
      pack(f, out, send[n]);
      req.emplace_back();
      MPI_Isend(send[n].data(), static_cast<int>(send[n].size() * sizeof(T)), MPI_BYTE, ls[n].rank,
                tag, comm_, &req.back());
    }
    MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
    for (std::size_t n = 0; n < ls.size(); ++n) {
      const IndexBox& in = reverse ? ls[n].mine_in_theirs : ls[n].theirs_in_mine;
      std::size_t m = 0;
      for (int k = in.k0; k < in.k1; ++k)
        for (int i = in.i0; i < in.i1; ++i, ++m) {
          if (reverse)
            f(i, k) += recv[n][m];
          else
            f(i, k) = recv[n][m];
        }
    }
  }

  // The neighbours of every array's staggering (links are symmetric: both sides agree on them),
  // one message each way per neighbour with the arrays' boxes one after the other.
  template <class T>
  void exchange_all(std::initializer_list<GridArray<T>*> fs, bool reverse) const {
    std::vector<int> ranks;
    for (const GridArray<T>* f : fs)
      for (const Link& l : links(f->stagger())) ranks.push_back(l.rank);
    if (ranks.empty()) return;
    core::ScopedTimer timer(reverse ? "halo: reverse add" : "halo: forward");
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
    std::vector<std::vector<T>> send(ranks.size()), recv(ranks.size());
    std::vector<MPI_Request> req(2 * ranks.size());
    std::vector<T> part;
    for (std::size_t n = 0; n < ranks.size(); ++n) {
      long long in_size = 0;
      for (const GridArray<T>* f : fs) {
        in_size += box_with(*f, ranks[n], false, reverse).size();
        pack(*f, box_with(*f, ranks[n], true, reverse), part);
        send[n].insert(send[n].end(), part.begin(), part.end());
      }
      recv[n].resize(static_cast<std::size_t>(in_size));
      MPI_Irecv(recv[n].data(), static_cast<int>(recv[n].size() * sizeof(T)), MPI_BYTE, ranks[n],
                760, comm_, &req[2 * n]);
      MPI_Isend(send[n].data(), static_cast<int>(send[n].size() * sizeof(T)), MPI_BYTE, ranks[n],
                760, comm_, &req[2 * n + 1]);
    }
    MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
    for (std::size_t n = 0; n < ranks.size(); ++n) {
      const T* p = recv[n].data();
      for (GridArray<T>* f : fs) {
        const IndexBox in = box_with(*f, ranks[n], false, reverse);
        unpack(*f, in, p, reverse);
        p += in.size();
      }
    }
  }

  MPI_Comm comm_;
  std::vector<Link> links_[3];
};

/// Collective: the array `f` laid out on `from` (this rank's old blocks) carried over to `to`
/// (the same grid and ranks, other cut lines). Every sample of the new storage window gets the
/// value of the rank that provided it on `from` (Decomposition::provided: the owner, or beyond
/// the walls the rank bordering them), so ghosts inside the grid take their owner's value.
template <class T>
GridArray<T> redistributed(const GridArray<T>& f, const Decomposition& from,
                           const Decomposition& to) {
  GridArray<T> g(to, f.stagger());
  const Stagger s = f.stagger();
  const int me = from.rank(), ranks = from.size();
  const MPI_Comm comm = from.comm().raw();
  const int tag = 740 + static_cast<int>(s);
  const IndexBox mine = from.provided(s, me), want = to.storage(s, me);
  std::vector<std::vector<T>> send(static_cast<std::size_t>(ranks)),
      recv(static_cast<std::size_t>(ranks));
  std::vector<MPI_Request> req;
  for (int r = 0; r < ranks; ++r) {
    if (r == me) continue;
    const IndexBox in = from.provided(s, r).intersect(want);
    if (in.empty()) continue;
    auto& buf = recv[static_cast<std::size_t>(r)];
    buf.resize(static_cast<std::size_t>(in.size()));
    req.emplace_back();
    MPI_Irecv(buf.data(), static_cast<int>(buf.size() * sizeof(T)), MPI_BYTE, r, tag, comm,
              &req.back());
  }
  for (int r = 0; r < ranks; ++r) {
    const IndexBox out = mine.intersect(to.storage(s, r));
    if (out.empty()) continue;
    if (r == me) {
      for (int k = out.k0; k < out.k1; ++k)
        for (int i = out.i0; i < out.i1; ++i) g(i, k) = f(i, k);
      continue;
    }
    auto& buf = send[static_cast<std::size_t>(r)];
    for (int k = out.k0; k < out.k1; ++k)
      for (int i = out.i0; i < out.i1; ++i) buf.push_back(f(i, k));
    req.emplace_back();
    MPI_Isend(buf.data(), static_cast<int>(buf.size() * sizeof(T)), MPI_BYTE, r, tag, comm,
              &req.back());
  }
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
  for (int r = 0; r < ranks; ++r) {
    if (r == me) continue;
    const IndexBox in = from.provided(s, r).intersect(want);
    if (in.empty()) continue;
    std::size_t m = 0;
    for (int k = in.k0; k < in.k1; ++k)
      for (int i = in.i0; i < in.i1; ++i) g(i, k) = recv[static_cast<std::size_t>(r)][m++];
  }
  return g;
}

}  // namespace picdem::grid
