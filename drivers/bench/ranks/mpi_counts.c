/* Counts the MPI messages a run sends (PMPI interposition, loaded with LD_PRELOAD): point-to-point
 * sends (number and bytes) and collective calls (number and the bytes each rank contributes).
 * At MPI_Finalize every rank appends one line to $MPI_COUNTS_FILE (default mpi_counts.txt):
 *   rank p2p_messages p2p_bytes collectives collective_bytes
 * Build: mpicc -O2 -shared -fPIC -o mpi_counts.so mpi_counts.c
 * Use:   mpirun -x LD_PRELOAD=$PWD/mpi_counts.so -x MPI_COUNTS_FILE=out.txt -n 4 picdem ...
 * (drivers/bench/ranks/messages_per_step.sh runs it on 1 to 8 ranks.) */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static long long p2p_n, p2p_bytes, coll_n, coll_bytes;

static long long bytes_of(int count, MPI_Datatype type) {
  int size = 0;
  PMPI_Type_size(type, &size);
  return (long long)count * size;
}

#define P2P(name, sig, call)                   \
  int name sig {                               \
    p2p_n++;                                   \
    p2p_bytes += bytes_of(count, datatype);    \
    return call;                               \
  }

P2P(MPI_Send, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm),
    PMPI_Send(buf, count, datatype, dest, tag, comm))
P2P(MPI_Ssend, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm),
    PMPI_Ssend(buf, count, datatype, dest, tag, comm))
P2P(MPI_Rsend, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm),
    PMPI_Rsend(buf, count, datatype, dest, tag, comm))
P2P(MPI_Isend, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm,
                MPI_Request* req),
    PMPI_Isend(buf, count, datatype, dest, tag, comm, req))
P2P(MPI_Issend, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm,
                 MPI_Request* req),
    PMPI_Issend(buf, count, datatype, dest, tag, comm, req))
P2P(MPI_Irsend, (const void* buf, int count, MPI_Datatype datatype, int dest, int tag, MPI_Comm comm,
                 MPI_Request* req),
    PMPI_Irsend(buf, count, datatype, dest, tag, comm, req))

int MPI_Allreduce(const void* s, void* r, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(count, datatype);
  return PMPI_Allreduce(s, r, count, datatype, op, c);
}
int MPI_Reduce(const void* s, void* r, int count, MPI_Datatype datatype, MPI_Op op, int root,
               MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(count, datatype);
  return PMPI_Reduce(s, r, count, datatype, op, root, c);
}
int MPI_Bcast(void* b, int count, MPI_Datatype datatype, int root, MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(count, datatype);
  return PMPI_Bcast(b, count, datatype, root, c);
}
int MPI_Scan(const void* s, void* r, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(count, datatype);
  return PMPI_Scan(s, r, count, datatype, op, c);
}
int MPI_Exscan(const void* s, void* r, int count, MPI_Datatype datatype, MPI_Op op, MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(count, datatype);
  return PMPI_Exscan(s, r, count, datatype, op, c);
}
int MPI_Allgather(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
                  MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(sc, st);
  return PMPI_Allgather(s, sc, st, r, rc, rt, c);
}
int MPI_Allgatherv(const void* s, int sc, MPI_Datatype st, void* r, const int* rc, const int* d,
                   MPI_Datatype rt, MPI_Comm c) {
  coll_n++, coll_bytes += bytes_of(sc, st);
  return PMPI_Allgatherv(s, sc, st, r, rc, d, rt, c);
}
int MPI_Alltoall(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
                 MPI_Comm c) {
  int n = 0;
  PMPI_Comm_size(c, &n);
  coll_n++, coll_bytes += bytes_of(sc, st) * n;
  return PMPI_Alltoall(s, sc, st, r, rc, rt, c);
}
int MPI_Alltoallv(const void* s, const int* sc, const int* sd, MPI_Datatype st, void* r,
                  const int* rc, const int* rd, MPI_Datatype rt, MPI_Comm c) {
  int n = 0;
  PMPI_Comm_size(c, &n);
  long long total = 0;
  for (int i = 0; i < n; ++i) total += sc[i];
  coll_n++, coll_bytes += bytes_of((int)total, st);
  return PMPI_Alltoallv(s, sc, sd, st, r, rc, rd, rt, c);
}
int MPI_Barrier(MPI_Comm c) {
  coll_n++;
  return PMPI_Barrier(c);
}

int MPI_Finalize(void) {
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char* path = getenv("MPI_COUNTS_FILE");
  FILE* f = fopen(path ? path : "mpi_counts.txt", "a");
  if (f) {
    fprintf(f, "%d %lld %lld %lld %lld\n", rank, p2p_n, p2p_bytes, coll_n, coll_bytes);
    fclose(f);
  }
  return PMPI_Finalize();
}
