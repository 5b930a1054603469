// The real scans of ../shared/data/real that the credibility test compares synthetic scans with:
// MulRan (KAIST03 PNGs, one DCC01 ray CSV), Oxford RobotCar and Boreas-RT.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "datasets/polar_image.hpp"
#include "datasets/polar_png.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr::test {

struct RealSource {
  std::string name;                // "MulRan", "Oxford", "Boreas"
  std::filesystem::path location;  // skipped when absent
  std::vector<PolarImage> scans;
};

inline std::vector<PolarImage> read_pngs(const std::vector<std::filesystem::path>& files,
                                         double resolution_m) {
  std::vector<PolarImage> scans;
  PolarPngOptions options;
  options.range_resolution_m = resolution_m;
  options.layout = PolarPngLayout::oxford;
  for (const auto& file : files) scans.push_back(read_polar_png(file, options).image);
  return scans;
}

inline std::vector<std::filesystem::path> pngs_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".png") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// MulRan's ray CSV: one line per azimuth, 4 metadata values then 3360 range bins.
inline PolarImage read_mulran_ray_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::uint8_t>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string value;
    std::vector<std::uint8_t> row;
    for (int column = 0; std::getline(fields, value, ','); ++column) {
      if (column >= 4) row.push_back(static_cast<std::uint8_t>(std::stoi(value)));
    }
    if (!row.empty()) rows.push_back(std::move(row));
  }
  PolarImage image;
  image.power = ByteImage(static_cast<int>(rows.size()), static_cast<int>(rows.front().size()));
  for (std::size_t a = 0; a < rows.size(); ++a) {
    std::copy(rows[a].begin(), rows[a].end(), image.power.row(static_cast<int>(a)));
  }
  image.azimuths_rad = uniform_azimuths(image.power.rows());
  image.range_resolution_m = 0.0595238;
  return image;
}

// Every real source present (absent ones are left out; the caller skips when none is there).
inline std::vector<RealSource> real_sources() {
  std::vector<RealSource> sources;
  const auto kaist = real_data("referee_mulran_kaist03/oxford_form");
  const auto dcc = real_data("mulran_dcc01_ray_csv/1564718976161407002.csv");
  if (std::filesystem::exists(kaist) || std::filesystem::exists(dcc)) {
    RealSource mulran{"MulRan", kaist, {}};
    if (std::filesystem::exists(kaist)) mulran.scans = read_pngs(pngs_in(kaist), 0.0595238);
    if (std::filesystem::exists(dcc)) mulran.scans.push_back(read_mulran_ray_csv(dcc));
    sources.push_back(std::move(mulran));
  }
  const auto oxford = real_data("oxford_radar_robotcar_tiny_radarslampy/radar");
  const auto oxford_extra = real_data("oxford_radar_robotcar_extra_evanflash");
  if (std::filesystem::exists(oxford)) {
    auto files = pngs_in(oxford);
    if (std::filesystem::exists(oxford_extra)) {
      for (const auto& f : pngs_in(oxford_extra)) files.push_back(f);
    }
    sources.push_back({"Oxford", oxford, read_pngs(files, 0.0432)});
  }
  const auto boreas = real_data("boreas_rt_single_frame/test_frame.png");
  if (std::filesystem::exists(boreas)) {
    sources.push_back({"Boreas", boreas, read_pngs({boreas}, 0.0438)});
  }
  return sources;
}

}  // namespace radarpr::test
