#include "datasets/scan_sequence.hpp"

namespace radarpr {

DatasetReport ScanSequence::describe() const {
  const auto& scans = records();
  DatasetReport report;
  report.name = name();
  report.location = name();
  report.scan_files = scans.size();
  report.window = "all";
  report.scans_selected = scans.size();
  report.position_frame = position_frame();
  if (report.position_frame != PositionFrame::none) report.posed_scans = scans.size();
  if (!scans.empty()) {
    report.scan_times = TimeSpan{scans.front().timestamp_ns, scans.back().timestamp_ns};
  }
  return report;
}

}  // namespace radarpr
