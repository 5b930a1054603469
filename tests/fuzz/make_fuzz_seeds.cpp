// Writes the generated seed corpus of the fuzz targets: small files of each format, valid and
// slightly broken, so that fuzzing starts from inputs that reach deep into each reader.
//   radarpr_fuzz_seeds OUT_FOLDER              generated seeds (committed as tests/fuzz/corpus)
//   radarpr_fuzz_seeds OUT_FOLDER REAL_FOLDER  also seeds from the real samples (pose files,
//                                              PNG scans), for a local fuzzing session only: the
//                                              real samples are never copied into the project
// Every seed starts with the byte its target reads first (the parser or options choice).
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "descriptors/plugins/plugin_compatibility.hpp"

namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, std::string_view bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string prefixed(int choice, std::string_view bytes) {
  std::string seed;
  seed.push_back(static_cast<char>(choice));
  seed.append(bytes);
  return seed;
}

std::string png_bytes(const cv::Mat& image) {
  std::vector<unsigned char> buffer;
  cv::imencode(".png", image, buffer);
  return {buffer.begin(), buffer.end()};
}

// An Oxford-layout scan: per row an int64 µs time, a uint16 encoder value, the valid flag, then
// the range bins.
cv::Mat oxford_scan(int azimuths, int bins) {
  cv::Mat image(azimuths, 11 + bins, CV_8UC1, cv::Scalar(0));
  for (int a = 0; a < azimuths; ++a) {
    const std::int64_t time_us = 1'600'000'000'000'000 + a * 625;
    const auto encoder = static_cast<std::uint16_t>(a * 5600 / azimuths);
    std::memcpy(image.ptr(a), &time_us, 8);
    std::memcpy(image.ptr(a) + 8, &encoder, 2);
    image.at<std::uint8_t>(a, 10) = 255;
    for (int r = 0; r < bins; ++r)
      image.at<std::uint8_t>(a, 11 + r) = static_cast<std::uint8_t>((a * 7 + r * 13) % 256);
  }
  return image;
}

void polar_png_seeds(const fs::path& out) {
  const std::string oxford = png_bytes(oxford_scan(16, 40));
  cv::Mat native(40, 16, CV_8UC1);
  cv::randu(native, 0, 255);
  const std::string native_png = png_bytes(native);
  for (const int choice : {0, 1, 4})
    write(out / fmt::format("oxford_{}.png", choice), prefixed(choice, oxford));
  for (const int choice : {0, 2})
    write(out / fmt::format("native_{}.png", choice), prefixed(choice, native_png));
  write(out / "oxford_truncated.png", prefixed(0, oxford.substr(0, oxford.size() - 20)));
  write(out / "oxford_header_only.png", prefixed(0, oxford.substr(0, 33)));
  write(out / "colour.png", prefixed(0, png_bytes(cv::Mat(8, 20, CV_8UC3, cv::Scalar(1, 2, 3)))));
  write(out / "sixteen_bit.png", prefixed(0, png_bytes(cv::Mat(8, 20, CV_16UC1, cv::Scalar(300)))));
}

void pose_seeds(const fs::path& out) {
  // The choice byte is the parser's index in pose_files_fuzz.cpp.
  write(out / "boreas.csv", prefixed(0,
                                     "GPSTime,easting,northing,altitude,heading\n"
                                     "1600000000000000,10.5,20.25,0,0.1\n"
                                     "1600000000250000,11.5,20.75,0,0.2\n"
                                     "1600000000500000,12.5,21.25,0,0.3\n"));
  write(out / "folder.csv", prefixed(1,
                                     "timestamp,x,y,yaw\n1567410201.5,0,0,0\n"
                                     "1567410202.5,10,20,1\n1567410203.5,10,30,-3.1\n"));
  write(out / "folder_no_yaw.csv",
        prefixed(1, "timestamp,x,y\n1567410201000000000,0,0\n1567410203000000000,-4,0\n"));
  std::string mulran;
  for (int i = 0; i < 4; ++i) {
    mulran +=
        fmt::format("{},1,0,0,{},0,1,0,{},0,0,1,0\n",
                    1'567'410'201'000'000'000 + std::int64_t{i} * 100'000'000, 100 + i, 200 - i);
  }
  write(out / "mulran.csv", prefixed(2, mulran));
  write(out / "oord.csv", prefixed(3,
                                   "timestamp,utm_northing,utm_easting,altitude\n"
                                   "1600000000.000,5000000.5,600000.25,10\n"
                                   "1600000000.500,5000001.5,600000.75,10\n"));
  write(out / "oxford_ins.csv",
        prefixed(4,
                 "timestamp,ins_status,latitude,longitude,altitude,northing,easting,down,"
                 "utm_zone,velocity_north,velocity_east,velocity_down,roll,pitch,yaw\n"
                 "1547131046353776,INS_SOLUTION_GOOD,51.7,-1.2,110,5735000.1,620000.2,-110,"
                 "30U,0,0,0,0,0,1.5\n"
                 "1547131046403776,INS_SOLUTION_GOOD,51.7,-1.2,110,5735000.3,620000.4,-110,"
                 "30U,0,0,0,0,0,1.6\n"));
  write(out / "oxford_gps.csv",
        prefixed(5, "timestamp,northing,easting\n1600000000000000,1,2\n1600000000100000,2,3\n"));
  write(out / "oxford_odometry.csv",
        prefixed(6,
                 "source_timestamp,destination_timestamp,x,y,z,roll,pitch,yaw,"
                 "source_radar_timestamp,destination_radar_timestamp\n"
                 "0,0,1,0,0,0,0,0,1547131000250000,1547131000000000\n"
                 "0,0,1,0,0,0,0,1.5707963,1547131000500000,1547131000250000\n"
                 "0,0,1,0,0,0,0,0,1547131000750000,1547131000500000\n"));
  write(out / "radiate.txt",
        prefixed(7, "Frame: 000001 Time: 1574859772.0\nFrame: 000002 Time: 1574859772.25\n"));
  write(out / "unix_seconds.txt", prefixed(8, "1574859771.744660272"));
  write(out / "unix_microseconds.txt", prefixed(8, "1547131046353776"));
  write(out / "unix_nanoseconds.txt", prefixed(8, "1567410201812840928"));
}

void config_seeds(const fs::path& out) {
  write(out / "overrides.json",
        "--set protocol.revisit_radius_m=15\n--set datasets.0.query.scans=30\n"
        "{\"experiment\": \"fuzz\", \"datasets\": [{\"name\": \"town\", \"query\": "
        "{\"type\": \"synthetic\", \"seed\": 7, \"session\": 0, \"scans\": 40}}], "
        "\"descriptors\": [\"referee\", {\"name\": \"referee_r\", \"params\": "
        "{\"kernel\": \"box\"}}], \"protocol\": {\"exclude_recent_frames\": 5, "
        "\"revisit_radius_m\": 20}}\n");
  write(out / "bad_override.json", "--set protocol\n{\"experiment\": \"x\"}\n");
  write(out / "real_dataset.json",
        "{\"experiment\": \"real\", \"datasets\": [{\"name\": \"ox\", \"query\": "
        "{\"type\": \"oxford\", \"root\": \"${HOME}/data\", \"sequence\": \"2019-01-10\", "
        "\"every_nth\": 4, \"max_pose_gap_s\": 2}}], \"descriptors\": [\"raplace\"]}\n");
}

void plugin_abi_seeds(const fs::path& out) {
  const RadarprPluginAbi& host = radarpr::host_plugin_abi();
  const std::string record(reinterpret_cast<const char*>(&host),
                           offsetof(RadarprPluginAbi, compiler));
  std::string host_seed = record;
  host_seed.append(host.compiler);
  host_seed.push_back('\0');
  host_seed.append("a.so:/b/c.so::d.so");
  write(out / "host.bin", host_seed);
  RadarprPluginAbi older = host;
  older.version_minor += 1;
  std::string older_seed(reinterpret_cast<const char*>(&older),
                         offsetof(RadarprPluginAbi, compiler));
  older_seed.append("gcc");
  older_seed.push_back('\0');
  write(out / "other_minor.bin", older_seed);
}

// Real samples as seeds for a local session: the pose files (first 50 lines) and one PNG scan.
void real_seeds(const fs::path& out, const fs::path& real) {
  // Both folders exist even when no sample matched: a fuzz test may be given them as corpora.
  fs::create_directories(out / "pose_files");
  fs::create_directories(out / "polar_png");
  const struct {
    const char* file;
    int parser;
  } pose_files[] = {
      {"poses_only/boreas-2021-08-05-13-34_radar_poses.csv", 0},
      {"oxford_radar_robotcar_tiny_radarslampy/gps/gps.csv", 5},
      {"oxford_radar_robotcar_tiny_radarslampy/gt/radar_odometry.csv", 6},
      {"poses_only/oxford_2019-01-10-11-46-21_radar_odometry.csv", 6},
  };
  for (const auto& [file, parser] : pose_files) {
    const fs::path path = real / file;
    if (!fs::exists(path)) continue;
    std::ifstream in(path);
    std::string head, line;
    for (int i = 0; i < 50 && std::getline(in, line); ++i) head += line + "\n";
    write(out / "pose_files" / path.filename(), prefixed(parser, head));
  }
  for (const auto& entry : fs::recursive_directory_iterator(real)) {
    if (entry.path().extension() == ".png" && entry.file_size() < 1'000'000) {
      write(out / "polar_png" / entry.path().filename(), prefixed(0, read(entry.path())));
      break;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: %s OUT_FOLDER [REAL_SAMPLES_FOLDER]\n", argv[0]);
    return 2;
  }
  try {
    const fs::path out = argv[1];
    if (argc == 3) {
      real_seeds(out, argv[2]);
      return 0;
    }
    polar_png_seeds(out / "polar_png");
    pose_seeds(out / "pose_files");
    config_seeds(out / "config");
    plugin_abi_seeds(out / "plugin_abi");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "radarpr_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
