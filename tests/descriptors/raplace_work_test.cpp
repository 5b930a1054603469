// Where RaPlace's exhaustive search spends its work: each value's spectra once per search, and
// per (query, database) pair exactly one spectral product and one inverse transform.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/raplace/circular_correlation.hpp"

namespace radarpr {
namespace {

std::vector<DescriptorValue> random_values(std::size_t count, const DescriptorShape& shape,
                                           unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<float> element;
  std::vector<DescriptorValue> values;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<float> v(shape.element_count());
    for (float& x : v) x = element(generator);
    values.push_back({shape.rows, shape.cols, std::move(v)});
  }
  return values;
}

raplace::CorrelationWork since(const raplace::CorrelationWork& before) {
  const raplace::CorrelationWork now = raplace::correlation_work();
  return {now.spectra - before.spectra, now.spectral_products - before.spectral_products,
          now.inverse_transforms - before.inverse_transforms};
}

TEST(RaplaceWork, SpectraOncePerValueAndOneProductAndInversePerPair) {
  for (const char* id : {"raplace", "raplace:shift_axis=rho"}) {
    SCOPED_TRACE(id);
    const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(id);
    const DescriptorShape shape = instance.descriptor->shape({});
    const auto queries = random_values(5, shape, 1);
    const auto database = random_values(7, shape, 2);

    // Preparing: 5 + 7 spectra, and each query's C(Dq, Dq) (5 products and inverses).
    raplace::CorrelationWork before = raplace::correlation_work();
    const auto prepared = instance.descriptor->prepare_distances(queries, database);
    raplace::CorrelationWork work = since(before);
    EXPECT_EQ(work.spectra, 12u);
    EXPECT_EQ(work.spectral_products, 5u);
    EXPECT_EQ(work.inverse_transforms, 5u);

    // Every pair: no spectrum, one product, one inverse transform.
    before = raplace::correlation_work();
    for (std::size_t q = 0; q < queries.size(); ++q) {
      for (std::size_t i = 0; i < database.size(); ++i) prepared->distance(q, i);
    }
    work = since(before);
    EXPECT_EQ(work.spectra, 0u);
    EXPECT_EQ(work.spectral_products, 35u);
    EXPECT_EQ(work.inverse_transforms, 35u);

    // A single session passes one vector twice: its spectra are computed once.
    before = raplace::correlation_work();
    const auto single = instance.descriptor->prepare_distances(database, database);
    EXPECT_EQ(since(before).spectra, 7u);
  }
}

}  // namespace
}  // namespace radarpr
