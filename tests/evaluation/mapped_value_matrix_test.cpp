// Descriptor values memory-mapped from a .npy file as one matrix (mapped_value_matrix.hpp), and
// the blocked L2 search reading them in place.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "datasets/npy_file.hpp"
#include "evaluation/mapped_value_matrix.hpp"
#include "evaluation/retrieval/retrieval.hpp"
#include "tests/evaluation/fake_descriptors.hpp"
#include "tests/evaluation/retrieval/retrieval_reference.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

class MappedValueMatrixTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("radarpr_mapped_values_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  // `count` values of rows x cols floats, drawn from a normal distribution.
  std::vector<float> random_floats(std::size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> element(0.0f, 1.0f);
    std::vector<float> floats(count);
    for (float& x : floats) x = element(rng);
    return floats;
  }

  // The message of the NpyError that opening `path` throws ("" when it opens).
  static std::string open_error(const fs::path& path) {
    try {
      MappedValueMatrix::open(path);
    } catch (const NpyError& error) {
      return error.what();
    }
    return "";
  }

  fs::path folder_;
};

TEST_F(MappedValueMatrixTest, MapsAFloat32ArrayAsRowsOfValues) {
  const std::vector<float> floats = random_floats(5 * 2 * 3, 1);
  const fs::path path = folder_ / "values.npy";
  write_npy(path, {5, 2, 3}, std::span<const float>(floats));
  const MappedValueMatrix matrix = MappedValueMatrix::open(path);
  EXPECT_EQ(matrix.path(), path);
  EXPECT_EQ(matrix.size(), 5u);
  EXPECT_EQ(matrix.rows(), 2);
  EXPECT_EQ(matrix.cols(), 3);
  EXPECT_EQ(matrix.dimension(), 6u);
  EXPECT_EQ(std::vector<float>(matrix.data(), matrix.data() + floats.size()), floats);
  matrix.release(0, 5);  // a hint: the values read the same afterwards
  EXPECT_EQ(std::vector<float>(matrix.data(), matrix.data() + floats.size()), floats);

  // count x floats: one column per float.
  const fs::path flat = folder_ / "flat.npy";
  write_npy(flat, {3, 10}, std::span<const float>(floats.data(), 30));
  const MappedValueMatrix two_d = MappedValueMatrix::open(flat);
  EXPECT_EQ(two_d.size(), 3u);
  EXPECT_EQ(two_d.rows(), 10);
  EXPECT_EQ(two_d.cols(), 1);
}

TEST_F(MappedValueMatrixTest, RefusesTruncatedFilesNamingThem) {
  const std::vector<float> floats = random_floats(4 * 8, 2);
  const fs::path path = folder_ / "truncated.npy";
  write_npy(path, {4, 8}, std::span<const float>(floats));
  fs::resize_file(path, fs::file_size(path) - 4);
  const std::string error = open_error(path);
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;

  fs::resize_file(path, 20);  // inside the header
  EXPECT_NE(open_error(path).find(path.string()), std::string::npos);
  EXPECT_NE(open_error(folder_ / "missing.npy").find("missing.npy"), std::string::npos);
}

TEST_F(MappedValueMatrixTest, RefusesOtherDtypesAndShapesNamingTheFile) {
  const fs::path doubles = folder_ / "doubles.npy";
  write_npy(doubles, {2, 3}, std::span<const double>(std::vector<double>(6, 1.0)));
  const std::string dtype_error = open_error(doubles);
  EXPECT_NE(dtype_error.find(doubles.string()), std::string::npos) << dtype_error;
  EXPECT_NE(dtype_error.find("float32"), std::string::npos) << dtype_error;
  EXPECT_NE(dtype_error.find("float64"), std::string::npos) << dtype_error;

  const std::vector<float> floats(24, 1.0f);
  const fs::path one_d = folder_ / "one_d.npy";
  write_npy(one_d, {24}, std::span<const float>(floats));
  EXPECT_NE(open_error(one_d).find("1 dimensions"), std::string::npos) << open_error(one_d);
  const fs::path four_d = folder_ / "four_d.npy";
  write_npy(four_d, {2, 3, 2, 2}, std::span<const float>(floats));
  EXPECT_NE(open_error(four_d).find("4 dimensions"), std::string::npos) << open_error(four_d);
  const fs::path empty = folder_ / "empty.npy";
  write_npy(empty, {0, 24}, std::span<const float>());
  EXPECT_NE(open_error(empty).find("no values"), std::string::npos) << open_error(empty);
}

// The search streamed from the map finds what the in-memory search finds, single and multi
// session, and refuses mismatched lengths.
TEST_F(MappedValueMatrixTest, StreamedSearchEqualsTheInMemorySearch) {
  const testing::EuclideanFake descriptor(RetrievalMethod::exhaustive_l2);
  const std::size_t count = 700;
  const std::size_t dimension = 1100;
  const std::vector<float> floats = random_floats(count * dimension, 3);
  const fs::path path = folder_ / "session.npy";
  write_npy(path, {count, dimension}, std::span<const float>(floats));
  std::vector<DescriptorValue> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    values[i].rows = static_cast<int>(dimension);
    values[i].cols = 1;
    values[i].values.assign(floats.begin() + static_cast<std::ptrdiff_t>(i * dimension),
                            floats.begin() + static_cast<std::ptrdiff_t>((i + 1) * dimension));
  }
  const MappedValueMatrix matrix = MappedValueMatrix::open(path);
  const L2Rows rows = matrix.l2_rows();

  std::vector<std::size_t> single(count);
  for (std::size_t q = 0; q < count; ++q) single[q] = q >= 50 ? q - 50 : 0;
  testing::expect_same(retrieve_nearest_l2(descriptor, rows, rows, single, 4),
                       retrieve_nearest(descriptor, values, values, single, 4));

  std::vector<DescriptorValue> queries(values.begin(), values.begin() + 30);
  for (DescriptorValue& query : queries) query.values[5] += 0.5f;
  const std::vector<std::size_t> all(queries.size(), count);
  testing::expect_same(retrieve_nearest_l2(descriptor, rows, L2Rows(queries), all, 2),
                       retrieve_nearest(descriptor, values, queries, all, 2));

  std::vector<DescriptorValue> shorter = {values[0]};
  shorter[0].values.pop_back();
  EXPECT_THROW(retrieve_nearest_l2(descriptor, rows, L2Rows(shorter), {count}, 1),
               std::invalid_argument);
  const testing::EuclideanFake exhaustive(RetrievalMethod::exhaustive);
  EXPECT_THROW(retrieve_nearest_l2(exhaustive, rows, rows, single, 1), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
