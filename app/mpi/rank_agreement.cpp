#include "rank_agreement.h"

#include <iostream>
#include <map>

namespace voxray::mpi {

std::vector<std::string> gatherText(MPI_Comm comm, const std::string& text) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int length = int(text.size());
  std::vector<int> lengths(static_cast<size_t>(size)), offsets(static_cast<size_t>(size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int k = 0; k < size; ++k) {
    offsets[size_t(k)] = total;
    total += lengths[size_t(k)];
  }
  std::string all(rank == 0 ? size_t(total) : 0, '\0');
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, comm);
  std::vector<std::string> out;
  if (rank == 0)
    for (int k = 0; k < size; ++k)
      out.push_back(all.substr(size_t(offsets[size_t(k)]), size_t(lengths[size_t(k)])));
  return out;
}

bool allSucceeded(MPI_Comm comm, const std::string& error, const std::string& where) {
  int failed = error.empty() ? 0 : 1, anyFailed = 0;
  MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, comm);
  if (!anyFailed) return true;
  const std::vector<std::string> errors = gatherText(comm, error);
  const std::vector<std::string> places = gatherText(comm, where);
  int size = 1;
  MPI_Comm_size(comm, &size);
  // The same text from several ranks (a path none can open) is said once, naming them all.
  std::map<std::string, std::vector<int>> byText;
  std::vector<std::string> order;
  for (size_t k = 0; k < errors.size(); ++k) {
    if (errors[k].empty()) continue;
    if (!byText.count(errors[k])) order.push_back(errors[k]);
    byText[errors[k]].push_back(int(k));
  }
  for (const std::string& text : order) {
    const std::vector<int>& ranks = byText[text];
    std::string who = ranks.size() == 1 ? "rank " : "ranks ";
    for (size_t i = 0; i < ranks.size(); ++i) who += (i ? ", " : "") + std::to_string(ranks[i] + 1);
    who += " of " + std::to_string(size);
    if (ranks.size() == 1 && !places[size_t(ranks[0])].empty())
      who += " (" + places[size_t(ranks[0])] + ")";
    std::cerr << "voxray-mpi: " << who << ": " << text << "\n";
  }
  return false;
}

}  // namespace voxray::mpi
