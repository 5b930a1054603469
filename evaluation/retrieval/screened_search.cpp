#include "evaluation/retrieval/screened_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

#include "evaluation/parallel.hpp"
#include "evaluation/retrieval/neighbour_ranking.hpp"

namespace radarpr::retrieval_detail {
namespace {

// Queries per task, and database values per block that the task's queries share while it is in
// cache (256 RaPlace values are about 400 KB of float spectra).
constexpr std::size_t kQueriesPerTask = 64;
constexpr std::size_t kDatabaseBlock = 256;

// One query's screening: the k best scores so far, and every value that may still be within
// twice the error of the k-th best.
struct Screening {
  double error = 0.0;
  bool exact_only = false;  // no usable bound: every distance is computed
  std::vector<float> best;  // min-heap of the k best scores
  std::vector<std::pair<float, std::uint32_t>> near;

  double threshold(std::size_t k) const {
    if (best.size() < k) return -std::numeric_limits<double>::infinity();
    return static_cast<double>(best.front()) - 2.0 * error;
  }

  void add(float score, std::size_t index, std::size_t k) {
    if (best.size() < k) {
      best.push_back(score);
      std::push_heap(best.begin(), best.end(), std::greater<>());
    } else if (score > best.front()) {
      std::pop_heap(best.begin(), best.end(), std::greater<>());
      best.back() = score;
      std::push_heap(best.begin(), best.end(), std::greater<>());
    }
    if (static_cast<double>(score) >= threshold(k)) {
      near.emplace_back(score, static_cast<std::uint32_t>(index));
    }
  }

  // Drops the values the threshold has left behind once they pile up.
  void prune(std::size_t k) {
    if (near.size() < 4 * k + 1024) return;
    const double limit = threshold(k);
    std::erase_if(near,
                  [&](const auto& entry) { return static_cast<double>(entry.first) < limit; });
  }
};

}  // namespace

std::vector<std::vector<Neighbour>> retrieve_screened(const PreparedDistances& prepared,
                                                      const ScreenedDistances& screen,
                                                      std::size_t query_count,
                                                      const std::vector<std::size_t>& eligible_ends,
                                                      std::size_t k) {
  std::vector<std::vector<Neighbour>> results(query_count);
  const std::size_t tasks = (query_count + kQueriesPerTask - 1) / kQueriesPerTask;
  parallel_for(tasks, 0, [&](std::size_t task) {
    const std::size_t first = task * kQueriesPerTask;
    const std::size_t last = std::min(query_count, first + kQueriesPerTask);
    std::vector<Screening> screenings(last - first);
    std::size_t longest = 0;
    for (std::size_t q = first; q < last; ++q) {
      Screening& screening = screenings[q - first];
      screening.error = screen.score_error(q);
      screening.exact_only = !std::isfinite(screening.error) || screening.error < 0.0;
      if (!screening.exact_only) longest = std::max(longest, eligible_ends[q]);
    }
    // The task's screened queries, taken kMaxQueries at a time against each database block.
    std::vector<std::size_t> screened;
    for (std::size_t q = first; q < last; ++q) {
      if (!screenings[q - first].exact_only && eligible_ends[q] > 0) screened.push_back(q);
    }
    constexpr std::size_t kGroup = ScreenedDistances::kMaxQueries;
    std::vector<float> scores(kGroup * kDatabaseBlock);
    for (std::size_t begin = 0; begin < longest; begin += kDatabaseBlock) {
      for (std::size_t g = 0; g < screened.size(); g += kGroup) {
        // Queries still eligible in this block; their scores run to the group's longest end.
        std::size_t group[kGroup];
        std::size_t count = 0;
        std::size_t end = begin;
        for (std::size_t i = g; i < std::min(screened.size(), g + kGroup); ++i) {
          const std::size_t q = screened[i];
          if (eligible_ends[q] <= begin) continue;
          group[count++] = q;
          end = std::max(end, std::min(begin + kDatabaseBlock, eligible_ends[q]));
        }
        if (count == 0) continue;
        screen.scores(group, count, begin, end, scores.data());
        for (std::size_t i = 0; i < count; ++i) {
          const std::size_t q = group[i];
          Screening& screening = screenings[q - first];
          const float* row = scores.data() + i * (end - begin);
          const std::size_t own_end = std::min(end, eligible_ends[q]);
          for (std::size_t j = begin; j < own_end; ++j) screening.add(row[j - begin], j, k);
          screening.prune(k);
        }
      }
    }
    for (std::size_t q = first; q < last; ++q) {
      const Screening& screening = screenings[q - first];
      std::vector<Neighbour> ranked;
      const auto rank = [&](std::size_t j) {
        ranked.push_back({j, checked_distance(prepared.distance(q, j), q, j)});
      };
      if (screening.exact_only) {
        for (std::size_t j = 0; j < eligible_ends[q]; ++j) rank(j);
      } else {
        const double limit = screening.threshold(k);
        for (const auto& [score, j] : screening.near) {
          if (static_cast<double>(score) >= limit) rank(j);
        }
      }
      const std::size_t kept = std::min(k, ranked.size());
      std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(kept),
                        ranked.end(), nearer);
      ranked.resize(kept);
      results[q] = std::move(ranked);
    }
  });
  return results;
}

}  // namespace radarpr::retrieval_detail
