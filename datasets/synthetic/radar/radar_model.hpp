#pragma once

#include "datasets/scan_sequence.hpp"

namespace radarpr::synthetic {

// The simulated spinning radar. Power is in uint8 units of about 0.5 dB (Navtech-like): a
// linear power p maps to 20*log10(p) units.
struct RadarModel {
  int azimuth_count = 400;
  int range_bin_count = 1680;              // 100 m at the default resolution
  double range_resolution_m = 0.0595238;   // MulRan CIR204-H: 200 m / 3360 bins
  double beam_width_deg = 1.8;             // two-way -3 dB azimuth beam width (Navtech: 1.8)
  double range_spread_m = 0.25;            // std dev of a point echo along range
  double noise_floor_near = 16.0;          // receiver noise floor at 0 m (units) ...
  double noise_floor_far = 9.5;            // ... falling towards this far away
  double noise_floor_falloff_m = 40.0;     // e-folding distance of that fall
  double ground_clutter = 9.0;             // road return added in front of the first opaque
  double ground_clutter_falloff_m = 60.0;  // object, fading with range (shadows stay darker)
  double range_loss_per_m = 0.04;          // echo loss with range (units per metre)
  bool speckle = true;                     // multiplicative exponential speckle on every bin
  double speckle_correlation_m = 0.3;      // speckle varies smoothly over this range cell
  // Antenna side lobes: beyond the main lobe a strong echo leaks into azimuths up to
  // `sidelobe_reach_deg` away, `sidelobe_level` units below its peak at the first side lobe and
  // `sidelobe_decay_per_deg` units lower per degree further (the arcs around bright targets).
  double sidelobe_level = -52.0;
  double sidelobe_reach_deg = 12.0;
  double sidelobe_decay_per_deg = 1.5;
  // Multipath: an echo above `multipath_min_level` units that stops the beam returns a ghost at
  // twice its range (sensor - target - vehicle - target), `multipath_loss` units weaker.
  double multipath_loss = 30.0;
  double multipath_min_level = 80.0;
  // Spreading loss, units per decade of range beyond 10 m, on top of range_loss_per_m.
  double spreading_loss_per_decade = 0.0;
  // Weather: extra two-way attenuation per metre and backscatter of rain or snow near the
  // sensor (units at 0 m, e-folding over precipitation_falloff_m).
  double atmospheric_loss_per_m = 0.0;
  double precipitation_clutter = 0.0;
  double precipitation_falloff_m = 20.0;
};

// Throws std::invalid_argument naming the first bad field.
void validate(const RadarModel& radar);

// The sensor's motion during one revolution: row 0 is measured at `start`, row A/2 at
// `middle`, and the sweep would reach `end` at row A (the next revolution's first row); rows in
// between are interpolated linearly (x, y, and yaw along the shorter arc).
struct SensorSweep {
  Pose2D start;
  Pose2D middle;
  Pose2D end;

  static SensorSweep still(const Pose2D& pose) { return {pose, pose, pose}; }
  // Pose of row `a` of `azimuth_count`.
  Pose2D at_row(int a, int azimuth_count) const;
};

}  // namespace radarpr::synthetic
