#include "descriptors/raplace/raplace_distance.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace radarpr {
namespace {

std::vector<raplace::LineSpectra> spectra_of(const raplace::CircularCorrelation& correlation,
                                             const std::vector<DescriptorValue>& values,
                                             const char* which) {
  std::vector<raplace::LineSpectra> spectra;
  spectra.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const DescriptorValue& value = values[i];
    if (value.rows != correlation.rows() || value.cols != correlation.cols()) {
      throw std::invalid_argument(
          "raplace: " + std::string(which) + " value " + std::to_string(i) + " is " +
          std::to_string(value.rows) + " x " + std::to_string(value.cols) + ", expected " +
          std::to_string(correlation.rows()) + " x " + std::to_string(correlation.cols()));
    }
    spectra.push_back(correlation.spectra(value.values));
  }
  return spectra;
}

}  // namespace

double raplace_distance_from(RaplaceDistance kind, double self, double cross,
                             bool database_all_zero) {
  if (kind == RaplaceDistance::raw_over_1000) return (self - cross) / 1000.0;
  if (!(self > 0.0)) return database_all_zero ? 0.0 : 1.0;
  return (self - cross) / self;
}

RaplacePreparedDistances::RaplacePreparedDistances(const raplace::CircularCorrelation& correlation,
                                                   RaplaceDistance kind,
                                                   const std::vector<DescriptorValue>& queries,
                                                   const std::vector<DescriptorValue>& database)
    : correlation_(correlation), kind_(kind), shared_(&queries == &database) {
  query_spectra_ = spectra_of(correlation_, queries, "query");
  if (!shared_) database_spectra_ = spectra_of(correlation_, database, "database");
  self_similarity_.reserve(query_spectra_.size());
  for (const raplace::LineSpectra& spectra : query_spectra_) {
    self_similarity_.push_back(correlation_.max_correlation(spectra, spectra).value);
  }
  screen_.emplace(correlation_, query_spectra_, database_spectra());
}

void RaplacePreparedDistances::scores(const std::size_t* queries, std::size_t query_count,
                                      std::size_t begin, std::size_t end, float* out) const {
  screen_->max_correlations(queries, query_count, begin, end, out);
}

double RaplacePreparedDistances::score_error(std::size_t query) const {
  if (kind_ == RaplaceDistance::normalized && !(self_similarity_.at(query) > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return screen_->error(query);
}

double RaplacePreparedDistances::distance(std::size_t query, std::size_t database_index) const {
  const std::vector<raplace::LineSpectra>& database = database_spectra();
  if (query >= query_spectra_.size() || database_index >= database.size()) {
    throw std::out_of_range("raplace: distance between query " + std::to_string(query) +
                            " and database value " + std::to_string(database_index) + " of " +
                            std::to_string(query_spectra_.size()) + " queries and " +
                            std::to_string(database.size()) + " database values");
  }
  const raplace::LineSpectra& query_spectra = query_spectra_[query];
  const raplace::LineSpectra& database_spectra = database[database_index];
  const double cross = correlation_.max_correlation(query_spectra, database_spectra).value;
  return raplace_distance_from(kind_, self_similarity_[query], cross, database_spectra.all_zero);
}

}  // namespace radarpr
