// Crash safety, as a user meets it: `radarpr run` killed with SIGKILL while it renders scans,
// trains, extracts, evaluates, writes its results and writes its report, then run again. Each
// time the rerun finishes with results byte-identical to a clean run (every file but
// timing.json), and nothing the killed run left behind, in the cache or beside --out, is
// trusted or kept. A cache damaged by hand (descriptor entries and rendered scans flipped or
// cut short) is named in a warning and recomputed, with the same results.
//
// Each moment is found from the run's own output and files, never by a hook in the program:
// the progress lines on stderr, the rendered scans and descriptor entries appearing in the
// cache, and the staging folders of the results and the report. The run is killed as soon as
// the moment is seen (polled every millisecond), and what it left shows the phase was hit.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A multi-session town small enough that a cold run takes a few seconds, with a trainable
// descriptor (a training phase, on the database session) beside two that are not.
constexpr const char* kConfig = R"({
  "experiment": "crash_safety",
  "datasets": [
    {"name": "town",
     "query": {"type": "synthetic", "seed": 3, "session": 1, "scans": 150, "range_bins": 420,
               "range_resolution_m": 0.238, "route_blocks_x": 1, "route_origin_block_x": 1},
     "database": {"type": "synthetic", "seed": 3, "session": 0, "scans": 200, "range_bins": 420,
                  "range_resolution_m": 0.238, "route_blocks_x": 1}}
  ],
  "descriptors": ["referee", "open_radvlad:bin_dim=10", "radar_scan_context"],
  "protocol": {"exclude_recent_frames": 20, "revisit_radius_m": 10}
})";

// The query session's extraction is over (its last progress line).
constexpr const char* kQueryExtracted =
    "extracting synthetic(seed=3,session=1) (dataset 1/1): 150/150";

// Every file of a results folder but timing.json, by its path relative to `folder`.
std::map<std::string, std::string> results_files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().filename() == "timing.json") continue;
    files[fs::relative(entry.path(), folder).string()] = read_file(entry.path());
  }
  return files;
}

// The files below `folder` (recursively) whose name satisfies `match`.
std::vector<fs::path> files_named(const fs::path& folder,
                                  const std::function<bool(const std::string&)>& match) {
  std::vector<fs::path> found;
  std::error_code error;
  if (!fs::exists(folder, error)) return found;
  for (auto it = fs::recursive_directory_iterator(folder, error);
       it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (error) break;
    if (match(it->path().filename().string())) found.push_back(it->path());
  }
  return found;
}

std::size_t rendered_scans(const fs::path& cache) {
  return files_named(cache / "synthetic",
                     [](const std::string& name) {
                       return name.ends_with(".png") && !name.starts_with(".");
                     })
      .size();
}

// Scans being written: a temporary name, renamed to the scan's when whole.
std::vector<fs::path> temporary_scans(const fs::path& cache) {
  return files_named(cache / "synthetic", [](const std::string& name) {
    return name.find(".png.tmp") != std::string::npos;
  });
}

std::vector<fs::path> descriptor_entries(const fs::path& cache) {
  return files_named(cache / "descriptors", [](const std::string& name) {
    return name.ends_with(".json") && !name.starts_with(".");
  });
}

// A rendered-scan folder that the run had not finished (no `complete` marker).
bool has_incomplete_scan_folder(const fs::path& cache) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(cache / "synthetic", error)) {
    if (entry.is_directory() && !fs::exists(entry.path() / "complete")) return true;
  }
  return false;
}

// A `radarpr run` started in the background, its stdout and stderr going to a log file.
class RunningProgram {
 public:
  RunningProgram(const std::vector<std::string>& arguments, const fs::path& log) : log_(log) {
    std::vector<std::string> argv_text = {RADARPR_CLI_PATH};
    argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
    pid_ = ::fork();
    if (pid_ == 0) {
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0) ::_exit(126);
      ::dup2(fd, STDOUT_FILENO);
      ::dup2(fd, STDERR_FILENO);
      std::vector<char*> argv;
      for (auto& text : argv_text) argv.push_back(text.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
  }
  RunningProgram(const RunningProgram&) = delete;
  RunningProgram& operator=(const RunningProgram&) = delete;
  ~RunningProgram() {
    if (pid_ > 0 && !reaped_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }

  pid_t pid() const { return pid_; }
  std::string log() const { return read_file(log_); }

  // Polls `moment` every millisecond and kills the program with SIGKILL as soon as it holds.
  // False when the program ended first (or after `limit`, when it is killed anyway).
  bool kill_when(const std::function<bool()>& moment,
                 std::chrono::seconds limit = std::chrono::seconds(300)) {
    const auto until = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < until) {
      if (moment()) {
        ::kill(pid_, SIGKILL);
        reap();
        return true;
      }
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        reaped_ = true;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ::kill(pid_, SIGKILL);
    reap();
    return false;
  }

 private:
  void reap() {
    ::waitpid(pid_, nullptr, 0);
    reaped_ = true;
  }

  fs::path log_;
  pid_t pid_ = -1;
  bool reaped_ = false;
};

class CrashSafety : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / fmt::format("radarpr_crash_safety_{}", ::getpid());
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::ofstream(root_ / "config.json") << kConfig;
    // The clean run: its results are the reference, its cache the warm state later runs copy.
    const auto clean =
        run({"--out", (root_ / "clean").string(), "--cache-dir", (root_ / "clean_cache").string()});
    clean_ok_ = clean.exit_code == 0;
    clean_output_ = clean.output;
    if (!clean_ok_) return;
    reference_ = results_files(root_ / "clean");
    const auto earlier =
        run({"--out", (root_ / "earlier").string(), "--cache-dir", (root_ / "clean_cache").string(),
             "--set", "protocol.revisit_radius_m=15"});
    clean_ok_ = earlier.exit_code == 0;
    clean_output_ = earlier.output;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  void SetUp() override {
    ASSERT_TRUE(clean_ok_) << clean_output_;
    ASSERT_GT(reference_.size(), 20u);
    ASSERT_EQ(descriptor_entries(root_ / "clean_cache").size(), 6u);
  }

  static testing::CommandResult run(const std::vector<std::string>& arguments) {
    std::string line = "run " + (root_ / "config.json").string();
    for (const auto& argument : arguments) line += " '" + argument + "'";
    return testing::run_cli(line);
  }

  // A fresh cache and results folder for `name`: the cache holds `warm` of the clean run's
  // ("" nothing, "synthetic" the rendered scans, "all" the scans and descriptor values); with
  // "all", --out holds the results of an earlier run of the config with another revisit radius
  // (so a run killed while moving its files in leaves a mix of the two).
  fs::path prepare(const std::string& name, const std::string& warm) {
    const fs::path folder = root_ / name;
    fs::remove_all(folder);
    fs::create_directories(folder / "cache");
    if (warm == "all") fs::copy(root_ / "earlier", folder / "out", fs::copy_options::recursive);
    if (warm == "synthetic" || warm == "all") {
      fs::copy(root_ / "clean_cache" / "synthetic", folder / "cache" / "synthetic",
               fs::copy_options::recursive);
    }
    if (warm == "all") {
      fs::copy(root_ / "clean_cache" / "descriptors", folder / "cache" / "descriptors",
               fs::copy_options::recursive);
    }
    return folder;
  }

  // Starts a run in `folder`, kills it at `moment`; true when `hit` (what the killed run left)
  // shows that it was killed in the phase meant.
  bool kill_run(const fs::path& folder, const std::function<bool(const RunningProgram&)>& moment,
                const std::function<bool(pid_t)>& hit) {
    RunningProgram program({"run", (root_ / "config.json").string(), "--out",
                            (folder / "out").string(), "--cache-dir", (folder / "cache").string()},
                           folder / "killed.log");
    const bool killed = program.kill_when([&] { return moment(program); });
    return killed && hit(program.pid());
  }

  // The rerun after a kill: it succeeds, its results are the clean run's, and nothing the
  // killed run left is kept: no staging folder beside or inside --out, no temporary file in the
  // cache.
  void expect_rerun_reproduces(const fs::path& folder, const std::string& phase) {
    const auto rerun =
        run({"--out", (folder / "out").string(), "--cache-dir", (folder / "cache").string()});
    ASSERT_EQ(rerun.exit_code, 0) << phase << ": " << rerun.output;
    const auto files = results_files(folder / "out");
    for (const auto& [name, bytes] : reference_) {
      ASSERT_TRUE(files.contains(name)) << phase << ": " << name << " missing";
      EXPECT_TRUE(files.at(name) == bytes) << phase << ": " << name << " differs";
    }
    EXPECT_EQ(files.size(), reference_.size()) << phase;
    const auto leftovers = [](const std::string& name) {
      return name.find(".partial.") != std::string::npos || name.find(".tmp") != std::string::npos;
    };
    for (const auto& left : files_named(folder, leftovers)) {
      ADD_FAILURE() << phase << ": left behind: " << left;
    }
    EXPECT_EQ(descriptor_entries(folder / "cache").size(), 6u) << phase;
  }

  // Kills a run started from `warm` at `moment` until `hit` shows the phase was hit (at most
  // `attempts` times: on a busy machine a short phase can pass between two polls), each kill
  // followed by a rerun that must reproduce the clean results.
  void kill_and_rerun(const std::string& phase, const std::string& warm,
                      const std::function<bool(const fs::path&, const RunningProgram&)>& moment,
                      const std::function<bool(const fs::path&, pid_t)>& hit, int attempts = 4) {
    bool was_hit = false;
    for (int attempt = 0; attempt < attempts && !was_hit; ++attempt) {
      const fs::path folder = prepare(phase, warm);
      was_hit = kill_run(
          folder, [&](const RunningProgram& program) { return moment(folder, program); },
          [&](pid_t pid) { return hit(folder, pid); });
      // What the killed run left (shown, for the record of where kills land).
      const auto left = files_named(folder, [](const std::string& name) {
        return name.find(".partial.") != std::string::npos ||
               name.find(".tmp") != std::string::npos;
      });
      std::cout << fmt::format(
          "{}: kill {} {}; {} staging or temporary files left, {} rendered "
          "scans, {} descriptor entries\n",
          phase, attempt + 1, was_hit ? "in the phase" : "missed the phase", left.size(),
          rendered_scans(folder / "cache"), descriptor_entries(folder / "cache").size());
      expect_rerun_reproduces(folder, phase);
      if (HasFatalFailure()) return;
    }
    EXPECT_TRUE(was_hit) << "no kill landed in the " << phase << " phase in " << attempts
                         << " attempts";
  }

  static fs::path root_;
  static bool clean_ok_;
  static std::string clean_output_;
  static std::map<std::string, std::string> reference_;
};

fs::path CrashSafety::root_;
bool CrashSafety::clean_ok_ = false;
std::string CrashSafety::clean_output_;
std::map<std::string, std::string> CrashSafety::reference_;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Six kills, one per phase, each followed by a rerun that must reproduce the clean results.
// One test, so that the clean run is made once.
TEST_F(CrashSafety, KilledInEveryPhaseTheRerunReproducesTheCleanRun) {
  // From an empty cache: killed while scans are being rendered into it, preferably while one
  // is half written (its temporary file present), which the rerun must remove.
  kill_and_rerun(
      "rendering", "",
      [](const fs::path& folder, const RunningProgram&) {
        const std::size_t rendered = rendered_scans(folder / "cache");
        return (rendered >= 10 && !temporary_scans(folder / "cache").empty()) || rendered >= 60;
      },
      [](const fs::path& folder, pid_t) {
        return has_incomplete_scan_folder(folder / "cache") &&
               descriptor_entries(folder / "cache").empty();
      });

  // Scans cached, no descriptor values: killed while open_radvlad learns its codebook.
  kill_and_rerun(
      "training", "synthetic",
      [](const fs::path&, const RunningProgram& program) {
        return contains(program.log(), "  training open_radvlad");
      },
      [](const fs::path& folder, pid_t) { return descriptor_entries(folder / "cache").empty(); });

  // Killed after the query session's values are stored in the cache, while the database's are
  // extracted.
  kill_and_rerun(
      "extraction", "synthetic",
      [](const fs::path& folder, const RunningProgram& program) {
        return contains(program.log(), kQueryExtracted) &&
               descriptor_entries(folder / "cache").size() >= 3;
      },
      [](const fs::path& folder, pid_t) {
        return descriptor_entries(folder / "cache").size() < 6 &&
               !contains(read_file(folder / "killed.log"), "evaluating");
      });

  // Every value cached: killed while the queries are evaluated, before any result is written
  // (--out still holds the earlier run's).
  kill_and_rerun(
      "evaluation", "all",
      [](const fs::path&, const RunningProgram& program) {
        return contains(program.log(), "  evaluating ");
      },
      [](const fs::path& folder, pid_t pid) {
        return read_file(folder / "out" / "summary.json") ==
                   read_file(root_ / "earlier" / "summary.json") &&
               !fs::exists(folder / fmt::format("out.partial.{}", pid));
      });

  // Killed while the results are written aside (out.partial.<pid>) or moved in over an earlier
  // run's: the rerun removes the dead run's staging folder and replaces every file.
  kill_and_rerun(
      "results", "all",
      [](const fs::path& folder, const RunningProgram& program) {
        return fs::exists(folder / fmt::format("out.partial.{}", program.pid()));
      },
      [](const fs::path& folder, pid_t pid) {
        return fs::exists(folder / fmt::format("out.partial.{}", pid));
      });

  // Killed while the report is written aside (out/.report.partial.<pid>).
  kill_and_rerun(
      "report", "all",
      [](const fs::path& folder, const RunningProgram& program) {
        return fs::exists(folder / "out" / fmt::format(".report.partial.{}", program.pid()));
      },
      [](const fs::path& folder, pid_t pid) {
        return fs::exists(folder / "out" / fmt::format(".report.partial.{}", pid));
      });
}

// The cache damaged by hand: two descriptor entries with a flipped byte, one cut short, a
// rendered scan with a flipped byte in its image data, another cut short. Each is named in a
// warning and recomputed, the results are the clean run's, and the next run finds the cache
// repaired (no warning).
TEST_F(CrashSafety, DamagedCacheEntriesAreNamedAndRecomputed) {
  const fs::path folder = prepare("damaged", "all");
  const fs::path cache = folder / "cache";
  std::vector<fs::path> damaged;
  auto flip_middle = [&](const fs::path& file) {
    std::string bytes = read_file(file);
    ASSERT_GT(bytes.size(), 100u) << file;
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
    write_file(file, bytes);
    damaged.push_back(file);
  };
  auto cut_short = [&](const fs::path& file) {
    fs::resize_file(file, fs::file_size(file) / 2);
    damaged.push_back(file);
  };
  // Both sessions' referee values (so every scan of both is decoded again), and one of
  // open_radvlad's (so it is trained again).
  std::vector<fs::path> referee = files_named(cache / "descriptors" / "referee",
                                              [](auto& name) { return name.ends_with(".npy"); });
  ASSERT_EQ(referee.size(), 2u);
  flip_middle(referee[0]);
  cut_short(referee[1]);
  const auto radvlad = files_named(cache / "descriptors" / "open_radvlad",
                                   [](auto& name) { return name.ends_with(".npy"); });
  ASSERT_EQ(radvlad.size(), 2u);
  flip_middle(radvlad[0]);
  // One scan of each session: a flipped byte in the image data (found when it is decoded: the
  // CRC), and a scan cut short (found when the folder is opened).
  std::vector<fs::path> sessions;
  for (const auto& entry : fs::directory_iterator(cache / "synthetic")) {
    sessions.push_back(entry.path() / "scans");
  }
  ASSERT_EQ(sessions.size(), 2u);
  const auto first_scans =
      files_named(sessions[0], [](auto& name) { return name.ends_with(".png"); });
  const auto second_scans =
      files_named(sessions[1], [](auto& name) { return name.ends_with(".png"); });
  ASSERT_FALSE(first_scans.empty() || second_scans.empty());
  {
    const fs::path scan = first_scans.front();
    std::string bytes = read_file(scan);
    const std::size_t data = bytes.find("IDAT");
    ASSERT_NE(data, std::string::npos);
    ASSERT_LT(data + 40, bytes.size());
    bytes[data + 40] = static_cast<char>(bytes[data + 40] ^ 0x5a);
    write_file(scan, bytes);
    damaged.push_back(scan);
  }
  cut_short(second_scans.front());

  const auto repaired = run({"--out", (folder / "out").string(), "--cache-dir", cache.string()});
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  for (const auto& file : damaged) {
    EXPECT_TRUE(contains(repaired.output, file.string())) << "no warning names " << file << " in:\n"
                                                          << repaired.output;
  }
  const auto files = results_files(folder / "out");
  for (const auto& [name, bytes] : reference_) {
    ASSERT_TRUE(files.contains(name)) << name << " missing";
    EXPECT_TRUE(files.at(name) == bytes) << name << " differs";
  }
  EXPECT_EQ(files.size(), reference_.size());

  const auto again = run({"--out", (folder / "out").string(), "--cache-dir", cache.string()});
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_FALSE(contains(again.output, "warning: cached")) << again.output;
  EXPECT_FALSE(contains(again.output, "recomputing")) << again.output;
  EXPECT_FALSE(contains(again.output, "  training")) << again.output;
}

}  // namespace
}  // namespace radarpr
