#include "datasets/dataset_report.hpp"

#include <ctime>

#include <fmt/format.h>

namespace radarpr {

std::string_view to_string(PositionFrame frame) {
  switch (frame) {
    case PositionFrame::global:
      return "global";
    case PositionFrame::local:
      return "local";
    case PositionFrame::none:
      return "none";
  }
  return "unknown";
}

void add_standard_warnings(DatasetReport& report, double long_pose_gap_s) {
  auto& warnings = report.warnings;
  if (report.position_frame != PositionFrame::none) {
    if (report.scan_times && report.pose_times &&
        !report.scan_times->overlaps(*report.pose_times)) {
      warnings.push_back(fmt::format(
          "the pose clock ({} .. {}) does not overlap the scan clock ({} .. {}): no scan can be "
          "given a pose",
          format_utc(report.pose_times->first_ns), format_utc(report.pose_times->last_ns),
          format_utc(report.scan_times->first_ns), format_utc(report.scan_times->last_ns)));
    } else if (report.scans_without_pose > 0) {
      warnings.push_back(fmt::format(
          "{} of {} scans have no pose (outside the pose track or in a gap longer than the "
          "limit) and are skipped",
          report.scans_without_pose, report.scans_selected));
    }
    if (report.largest_pose_gap_s && *report.largest_pose_gap_s > long_pose_gap_s) {
      warnings.push_back(
          fmt::format("the pose track has a gap of {:.2f} s", *report.largest_pose_gap_s));
    }
    if (report.duplicated_pose_timestamps > 0) {
      warnings.push_back(fmt::format(
          "{} pose samples repeat an earlier sample's timestamp (the first one is kept)",
          report.duplicated_pose_timestamps));
    }
  }
  if (report.duplicated_scan_timestamps > 0) {
    warnings.push_back(fmt::format("{} scans share their timestamp with another scan",
                                   report.duplicated_scan_timestamps));
  }
  if (report.invalid_azimuth_rows && *report.invalid_azimuth_rows > 0) {
    warnings.push_back(fmt::format(
        "the first scan has {} of {} azimuth rows flagged as interpolated (flag byte != 255)",
        *report.invalid_azimuth_rows, report.azimuths));
  }
}

std::string format_utc(std::int64_t unix_ns) {
  const std::int64_t seconds =
      unix_ns >= 0 ? unix_ns / 1'000'000'000 : -((-unix_ns + 999'999'999) / 1'000'000'000);
  const auto millis = static_cast<int>((unix_ns - seconds * 1'000'000'000) / 1'000'000);
  const auto time = static_cast<std::time_t>(seconds);
  std::tm utc{};
  if (gmtime_r(&time, &utc) == nullptr) return fmt::format("{} ns", unix_ns);
  return fmt::format("{:04}-{:02}-{:02} {:02}:{:02}:{:02}.{:03} UTC", utc.tm_year + 1900,
                     utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis);
}

namespace {

std::string describe_span(const std::optional<TimeSpan>& span) {
  if (!span) return "n/a";
  return fmt::format("{} .. {} ({:.1f} s)", format_utc(span->first_ns), format_utc(span->last_ns),
                     span->seconds());
}

}  // namespace

std::string format_report(const DatasetReport& r, const std::string& indent) {
  std::string text;
  const auto line = [&](std::string_view key, const std::string& value) {
    text += fmt::format("{}{:<13} {}\n", indent, key, value);
  };
  line("type", r.type);
  line("location", r.location);
  line("layout", r.layout.empty() ? "n/a" : r.layout);
  line("geometry", r.azimuths > 0
                       ? fmt::format("{} azimuths x {} range bins, {} m/bin ({}), {:.1f} m reach",
                                     r.azimuths, r.range_bins, r.range_resolution_m,
                                     r.resolution_source, r.range_bins * r.range_resolution_m)
                       : std::string("unknown (no scan decoded)"));
  line("scans",
       fmt::format("{} found, window {}: {} selected", r.scan_files, r.window, r.scans_selected));
  line("scan times", describe_span(r.scan_times));
  if (!r.scan_time_reference.empty()) {
    line("scan moment", "a scan's time and pose refer to " + r.scan_time_reference);
  }
  line("duplicates", fmt::format("{} scans share a timestamp{}", r.duplicated_scan_timestamps,
                                 r.position_frame == PositionFrame::none
                                     ? std::string()
                                     : fmt::format(", {} pose samples repeat one",
                                                   r.duplicated_pose_timestamps)));
  if (r.scans_selected > 1 && r.scan_times && r.scan_times->seconds() > 0.0) {
    line("scan rate", fmt::format("{:.2f} Hz", static_cast<double>(r.scans_selected - 1) /
                                                   r.scan_times->seconds()));
  }
  line("positions", r.position_frame == PositionFrame::none
                        ? "none" + (r.pose_source.empty() ? "" : ": " + r.pose_source)
                        : fmt::format("{} frame{}", to_string(r.position_frame),
                                      r.pose_source.empty() ? "" : ", from " + r.pose_source));
  if (r.position_frame != PositionFrame::none) {
    line("pose samples", fmt::format("{}, {}", r.pose_samples, describe_span(r.pose_times)));
    line("pose gap", r.largest_pose_gap_s ? fmt::format("largest {:.3f} s", *r.largest_pose_gap_s)
                                          : std::string("n/a"));
    line("posed scans", fmt::format("{} of {} ({} without a pose)", r.posed_scans, r.scans_selected,
                                    r.scans_without_pose));
  }
  if (r.invalid_azimuth_rows) {
    line("invalid rows",
         fmt::format("{} of {} in the first scan", *r.invalid_azimuth_rows, r.azimuths));
  }
  for (const auto& note : r.notes) line("note", note);
  return text;
}

}  // namespace radarpr
