// Open-RadVLAD's codebook as a file: save_codebook writes what train() learnt, codebook= loads it
// instead of training, and the codebook's hash is the SHA-256 anyone can recompute from the file.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "datasets/npy_file.hpp"
#include "datasets/sha256.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/learnt_codebook.hpp"
#include "descriptors/open_radvlad/codebook_file.hpp"
#include "descriptors/open_radvlad/open_radvlad.hpp"
#include "descriptors/opencv_image.hpp"
#include "descriptors/vector_training_scans.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

class TempFolder {
 public:
  TempFolder()
      : path_(fs::temp_directory_path() / ("radarpr_codebook_test_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

PolarImage random_scan(int azimuths, int range_bins, std::uint64_t state) {
  PolarImage scan;
  cv::Mat bytes(azimuths, range_bins, CV_8UC1);
  cv::RNG(state).fill(bytes, cv::RNG::UNIFORM, 0, 256);
  scan.power = to_byte_image(bytes);
  scan.azimuths_rad = uniform_azimuths(azimuths);
  scan.range_resolution_m = 0.05;
  return scan;
}

VectorTrainingScans training_scans() {
  std::vector<PolarImage> scans;
  for (int i = 0; i < 3; ++i)
    scans.push_back(random_scan(40, 200, 100 + static_cast<std::uint64_t>(i)));
  return VectorTrainingScans(std::move(scans), "three random scans");
}

OpenRadVladParams small_params() {
  OpenRadVladParams params;
  params.spectra.min_bin = 4;
  params.spectra.max_bin = 0;
  params.spectra.bin_dim = 16;
  params.clusters = 4;
  params.max_iterations = 50;
  return params;
}

bool bit_identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() &&
         std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(OpenRadVladCodebookFile, TheSavedCodebookLoadsBackAndGivesTheSameValues) {
  const TempFolder folder;
  OpenRadVladParams saving = small_params();
  saving.save_codebook_file = (folder / "cb.npy").string();
  OpenRadVladDescriptor trained(saving);
  EXPECT_TRUE(trained.trainable());
  EXPECT_EQ(trained.codebook_sha256(), "");
  trained.train(training_scans());

  const NpyFile file = NpyFile::open(folder / "cb.npy");
  EXPECT_EQ(file.dtype(), NpyDtype::float32);
  EXPECT_EQ(file.shape(), (std::vector<std::size_t>{4, 16}));
  // The recorded hash is the SHA-256 of the file's data bytes.
  EXPECT_EQ(trained.codebook_sha256(), sha256_hex(file.bytes()));
  EXPECT_EQ(trained.codebook_saved_to(), (folder / "cb.npy").string());
  EXPECT_EQ(trained.codebook_loaded_from(), "");

  OpenRadVladParams loading = small_params();
  loading.codebook_file = (folder / "cb.npy").string();
  OpenRadVladDescriptor loaded(loading);
  EXPECT_FALSE(loaded.trainable());
  EXPECT_TRUE(loaded.is_trained());
  EXPECT_TRUE(bit_identical(loaded.codebook(), trained.codebook()));
  EXPECT_EQ(loaded.codebook_sha256(), trained.codebook_sha256());
  EXPECT_EQ(loaded.codebook_loaded_from(), (folder / "cb.npy").string());
  const PolarImage scan = random_scan(40, 200, 7);
  EXPECT_EQ(loaded.extract(scan).values, trained.extract(scan).values);
  EXPECT_THROW(loaded.train(training_scans()), std::logic_error);
}

TEST(OpenRadVladCodebookFile, TheHashIsHashlibsOverLittleEndianFloat32) {
  // /usr/bin/python3: hashlib.sha256(np.array([[1, 2], [3, 4.5]], '<f4').tobytes()).hexdigest()
  cv::Mat codebook = (cv::Mat_<float>(2, 2) << 1.0f, 2.0f, 3.0f, 4.5f);
  EXPECT_EQ(codebook_sha256(codebook),
            "dc6117e28f47614cff71be6892909d825d4f4e8c752cc337c42b287d3cdb0afd");
  // A strided view hashes its values, not the memory around them.
  cv::Mat wide = (cv::Mat_<float>(2, 3) << 1.0f, 2.0f, 9.0f, 3.0f, 4.5f, 9.0f);
  EXPECT_EQ(codebook_sha256(wide.colRange(0, 2)), codebook_sha256(codebook));
}

TEST(OpenRadVladCodebookFile, AFloat64CodebookIsRoundedToFloat32) {
  const TempFolder folder;
  const std::vector<double> values = {0.1, 0.2, 0.3, 0.4};
  write_npy(folder / "f64.npy", {2, 2}, std::span<const double>(values));
  const cv::Mat codebook = read_codebook(folder / "f64.npy", 2, 2);
  EXPECT_EQ(codebook.at<float>(1, 0), 0.3f);
}

TEST(OpenRadVladCodebookFile, BadFilesAreRefusedNamingTheFileAndWhatWasExpected) {
  const TempFolder folder;
  const fs::path missing = folder / "missing.npy";
  std::string message = error_of([&] { read_codebook(missing, 4, 16); });
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_NE(message.find("4 x 16 float32"), std::string::npos) << message;

  const std::vector<float> twelve(3 * 16, 0.5f);
  write_npy(folder / "shape.npy", {3, 16}, std::span<const float>(twelve));
  message = error_of([&] { read_codebook(folder / "shape.npy", 4, 16); });
  EXPECT_NE(message.find("shape (3 x 16)"), std::string::npos) << message;
  EXPECT_NE(message.find((folder / "shape.npy").string()), std::string::npos) << message;

  const std::vector<std::int64_t> integers(4 * 16, 1);
  write_npy(folder / "int.npy", {4, 16}, std::span<const std::int64_t>(integers));
  message = error_of([&] { read_codebook(folder / "int.npy", 4, 16); });
  EXPECT_NE(message.find("int64"), std::string::npos) << message;

  std::vector<float> with_nan(4 * 16, 0.5f);
  with_nan[17] = std::numeric_limits<float>::quiet_NaN();
  write_npy(folder / "nan.npy", {4, 16}, std::span<const float>(with_nan));
  message = error_of([&] { read_codebook(folder / "nan.npy", 4, 16); });
  EXPECT_NE(message.find("row 1, column 1"), std::string::npos) << message;

  // The descriptor refuses the same file when constructed, and both switches at once.
  OpenRadVladParams params = small_params();
  params.codebook_file = (folder / "shape.npy").string();
  EXPECT_THROW(OpenRadVladDescriptor{params}, std::invalid_argument);
  params.codebook_file = (folder / "cb.npy").string();
  params.save_codebook_file = (folder / "other.npy").string();
  message = error_of([&] { OpenRadVladDescriptor{params}; });
  EXPECT_NE(message.find("exclude each other"), std::string::npos) << message;
}

TEST(OpenRadVladCodebookFile, AnUnwritableSaveFileFailsTrainingAndLeavesItUntrained) {
  const TempFolder folder;
  OpenRadVladParams params = small_params();
  params.save_codebook_file = (folder / "no_such_folder" / "cb.npy").string();
  OpenRadVladDescriptor vlad(params);
  const std::string message = error_of([&] { vlad.train(training_scans()); });
  EXPECT_NE(message.find("no_such_folder"), std::string::npos) << message;
  EXPECT_FALSE(vlad.is_trained());
}

TEST(OpenRadVladCodebookFile, TheRegistryLoadsAndSavesThroughParameters) {
  const TempFolder folder;
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  const DescriptorInstance saving = registry.create_from_id(
      "open_radvlad:bin_dim=16,clusters=4,min_bin=4,save_codebook=" + (folder / "cb.npy").string());
  auto trained = saving.create_fresh();
  trained->train(training_scans());
  const DescriptorInstance loading = registry.create_from_id(
      "open_radvlad:bin_dim=16,clusters=4,codebook=" + (folder / "cb.npy").string() + ",min_bin=4");
  ASSERT_NE(learnt_codebook_of(*loading.descriptor), nullptr);
  EXPECT_EQ(learnt_codebook_of(*loading.descriptor)->codebook_sha256(),
            learnt_codebook_of(*trained)->codebook_sha256());
  EXPECT_FALSE(loading.descriptor->trainable());
  const PolarImage scan = random_scan(40, 200, 11);
  EXPECT_EQ(loading.descriptor->extract(scan).values, trained->extract(scan).values);
}

}  // namespace
}  // namespace radarpr
