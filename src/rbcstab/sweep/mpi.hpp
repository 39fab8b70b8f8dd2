#pragma once
// MPI for diagrams (OpenMPI, `mpirun -np N rbcstab diagram ...`): rank r computes the points with
// index % N == r (a Shard, with its own threads and journal) and rank 0 gathers them. Built only
// with RBCSTAB_WITH_MPI; otherwise, and when the process was not started by mpirun, the session is
// a single rank and gather is the identity.
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

class MpiSession {
 public:
  MpiSession();   // MPI_Init_thread when started by mpirun (OMPI_COMM_WORLD_SIZE / PMI_SIZE set)
  ~MpiSession();  // MPI_Finalize if this session initialised MPI
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // The slice of the grid this process computes: its rank's under mpirun (where a shard of its own is refused:
  // the ranks already split the grid), else `given`.
  Shard shard(const Shard& given) const;
  // Rank 0 gets every rank's points in index order (complete iff every rank completed); other
  // ranks get their own run back, with `complete` as the global value.
  DiagramRun gather(const DiagramRun& mine, const DiagramSpec& spec) const;

 private:
  int rank_ = 0, size_ = 1;
  [[maybe_unused]] bool owner_ = false;  // this session called MPI_Init (unused without MPI)
};

}  // namespace rbcstab
