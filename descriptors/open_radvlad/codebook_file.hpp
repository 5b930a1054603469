#pragma once

#include <filesystem>
#include <string>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Open-RadVLAD's codebook as a numpy file: a 2-D array, one centre per row (clusters x bin_dim),
// so that np.load gives what scikit-learn's KMeans.cluster_centers_ holds.

// Reads a clusters x bin_dim float32 or float64 array (float64 values are rounded to float32, the
// type the VLAD uses) into a CV_32FC1 matrix. Throws std::invalid_argument naming the file and
// what was expected for a missing or unreadable file, another shape or dtype, or a non-finite
// value.
cv::Mat read_codebook(const std::filesystem::path& path, int clusters, int bin_dim);

// Writes a CV_32FC1 codebook as a float32 .npy (atomically: readers never see half a file).
// Throws std::invalid_argument naming the file when it cannot be written.
void write_codebook(const std::filesystem::path& path, const cv::Mat& codebook);

// SHA-256 (hex) of the codebook's float32 values, little-endian, row-major.
std::string codebook_sha256(const cv::Mat& codebook);

}  // namespace radarpr
