#include "tables.hpp"

#include "pool.hpp"

namespace ringlet::experiments {

std::vector<LearnerRow> compare_learners(const std::vector<planning::Experience>& data,
                                         const std::vector<NamedLearner>& learners, int folds, std::uint64_t seed,
                                         int threads, Progress& progress, const std::string& phase) {
  progress.begin(phase, learners.size());
  auto rows = run_indexed<LearnerRow>(learners.size(), threads, [&](std::size_t i) {
    const NamedLearner& l = learners[i];
    LearnerRow row{l.name, data.size(), planning::cross_validate(data, folds, seed, l.make).scores,
                   l.paper_error_pct, l.paper_correlation};
    progress.step(l.name);
    return row;
  });
  progress.end();
  return rows;
}

}  // namespace ringlet::experiments
