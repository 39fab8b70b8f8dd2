#include "rbcstab/sweep/mpi.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/sweep/point_record.hpp"

#ifdef RBCSTAB_WITH_MPI
#include <mpi.h>
#endif

namespace rbcstab {

MpiSession::MpiSession() {
#ifdef RBCSTAB_WITH_MPI
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
  if (!launched) return;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = 0;
    // Only the main thread calls MPI (workers never do): FUNNELED is enough.
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    owner_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

MpiSession::~MpiSession() {
#ifdef RBCSTAB_WITH_MPI
  if (owner_) MPI_Finalize();
#endif
}

Shard MpiSession::shard(const Shard& given) const {
  if (size_ == 1) return given;
  if (given.n > 1)
    throw InvalidArgument("shard", "shard = " + std::to_string(given.k) + "/" + std::to_string(given.n) +
                                       " cannot be combined with mpirun (the ranks already split the grid)");
  return Shard{rank_, size_};
}

DiagramRun MpiSession::gather(const DiagramRun& mine, const DiagramSpec& spec) const {
  if (size_ <= 1) return mine;
#ifdef RBCSTAB_WITH_MPI
  std::string text;
  for (const PointResult& p : mine.points) text += point_to_line(p, mine.config_hash);
  if (text.size() > std::size_t(1) << 30) throw std::runtime_error("MPI gather: a rank's results exceed 1 GiB");
  int n = int(text.size());
  std::vector<int> counts(static_cast<std::size_t>(size_)), displs(static_cast<std::size_t>(size_));
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank_ == 0) {
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
      displs[std::size_t(r)] = int(total);
      total += counts[std::size_t(r)];
    }
    if (total > (1ll << 31) - 1) throw std::runtime_error("MPI gather: results exceed 2 GiB");
    all.resize(std::size_t(total));
  }
  MPI_Gatherv(text.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  int complete = mine.complete ? 1 : 0, all_complete = 0;
  MPI_Allreduce(&complete, &all_complete, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  unsigned long long sums[2] = {mine.computed, mine.resumed}, totals[2] = {0, 0};
  MPI_Reduce(sums, totals, 2, MPI_UNSIGNED_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
  DiagramRun out = mine;
  out.complete = all_complete == 1;
  if (rank_ != 0) return out;
  std::map<std::size_t, PointResult> points;
  std::size_t pos = 0;
  while (pos < all.size()) {
    const auto eol = all.find('\n', pos);
    const std::string line = all.substr(pos, eol == std::string::npos ? std::string::npos : eol + 1 - pos);
    if (auto p = point_from_line(line, mine.config_hash, spec))
      points.emplace(p->index, *p);
    else
      throw std::runtime_error("MPI gather: a rank sent a malformed point");
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  out.points.clear();
  for (auto& [idx, p] : points) out.points.push_back(std::move(p));
  out.computed = std::size_t(totals[0]);
  out.resumed = std::size_t(totals[1]);
  out.complete = out.complete && out.points.size() == spec.size();
  return out;
#else
  (void)spec;
  return mine;
#endif
}

}  // namespace rbcstab
