#pragma once

#include <cstdint>

#include "datasets/byte_image.hpp"
#include "datasets/synthetic/radar/echo_buffer.hpp"
#include "datasets/synthetic/radar/radar_model.hpp"

namespace radarpr::synthetic {

// Renderer internals: the receiver. Adds the echoes to the noise floor (and the ground clutter
// in front of each ray's first opaque object), multiplies by speckle seeded by `noise_seed`,
// compresses to units (20 log10 power) and saturates to uint8: A x R bytes.
ByteImage quantise(const EchoBuffer& echoes, const RadarModel& radar, std::uint64_t noise_seed);

}  // namespace radarpr::synthetic
