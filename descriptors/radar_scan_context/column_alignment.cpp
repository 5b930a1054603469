#include "descriptors/radar_scan_context/column_alignment.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/cpu_features.hpp"

// The AVX2 build of the shift sums exists on x86-64 only; elsewhere the default build runs.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RADARPR_COLUMN_ALIGNMENT_X86 1
#endif

namespace radarpr {
namespace {

// A context's columns scaled to unit length, stored column after column so that a column is
// contiguous; an all-zero column stays zero and is marked unusable (its cosine is undefined).
struct UnitColumns {
  std::vector<double> values;        // sectors x rings
  std::vector<std::uint8_t> usable;  // per column, 1 = non-zero (a byte: read in the hot loop)
};

UnitColumns unit_columns(std::span<const float> context, std::size_t rings, std::size_t sectors,
                         std::string_view which) {
  UnitColumns columns{std::vector<double>(rings * sectors), std::vector<std::uint8_t>(sectors, 0)};
  for (std::size_t j = 0; j < sectors; ++j) {
    double* column = columns.values.data() + j * rings;
    double squared_norm = 0.0;
    for (std::size_t i = 0; i < rings; ++i) {
      const double value = context[i * sectors + j];
      if (!std::isfinite(value)) {
        throw std::invalid_argument("radar_scan_context: context " + std::string(which) +
                                    " holds a non-finite value at ring " + std::to_string(i) +
                                    ", sector " + std::to_string(j));
      }
      column[i] = value;
      squared_norm += value * value;  // float inputs cannot overflow a double sum
    }
    if (squared_norm == 0.0) continue;
    const double inverse_norm = 1.0 / std::sqrt(squared_norm);
    for (std::size_t i = 0; i < rings; ++i) column[i] *= inverse_norm;
    columns.usable[j] = 1;
  }
  return columns;
}

// Four shifts side by side: lane t holds shift s + t. Every lane sums its products in the
// scalar order (ring by ring, column by column), so the result is bit for bit the scalar one.
// Aligned like a double: containers need no over-aligned allocation.
// may_alias: read straight from the double arrays.
typedef double Shifts
    __attribute__((vector_size(4 * sizeof(double)), aligned(sizeof(double)), may_alias));
constexpr int kLanes = 4;
constexpr int kGroups = 5;  // 20 shifts per pass: five independent chains of sums (named below)
constexpr int kPass = kLanes * kGroups;

// a's columns in reversed order, ring-major, and extended by one pass: column c of `reversed` is
// a's column (-c) mod sectors, so the source columns (j - s - t) mod sectors of the shifts
// s0 + t, t = 0 .. kPass - 1, are the consecutive columns (s0 - j) mod sectors + t.
struct ReversedColumns {
  std::size_t width = 0;       // sectors + kPass
  std::vector<double> values;  // rings x width
  std::vector<double> usable;  // width: 1.0 or 0.0
};

ReversedColumns reversed_columns(const UnitColumns& a, std::size_t rings, std::size_t sectors) {
  ReversedColumns reversed;
  reversed.width = sectors + kPass;
  reversed.values.assign(rings * reversed.width, 0.0);
  reversed.usable.assign(reversed.width, 0.0);
  for (std::size_t c = 0; c < reversed.width; ++c) {
    const std::size_t source = (sectors - c % sectors) % sectors;
    for (std::size_t i = 0; i < rings; ++i) {
      reversed.values[i * reversed.width + c] = a.values[source * rings + i];
    }
    reversed.usable[c] = a.usable[source] ? 1.0 : 0.0;
  }
  return reversed;
}

// Four doubles from `from` (through a reference: returning the vector would change the ABI
// between the AVX2 and the default build).
inline void load(Shifts& value, const double* from) {
  value = *reinterpret_cast<const Shifts*>(from);
}

// cosine_sum[s] and pairs[s] of every shift, as the scalar definition sums them.
__attribute__((always_inline)) inline void shift_sums(const ReversedColumns& a,
                                                      const UnitColumns& b, std::size_t rings,
                                                      std::size_t sectors, double* cosine_sums,
                                                      double* pair_counts) {
  for (std::size_t s0 = 0; s0 < sectors; s0 += kPass) {
    Shifts cosine[kGroups];
    Shifts pairs[kGroups];
    for (int g = 0; g < kGroups; ++g) {
      cosine[g] = Shifts{0.0, 0.0, 0.0, 0.0};
      pairs[g] = Shifts{0.0, 0.0, 0.0, 0.0};
    }
    for (std::size_t j = 0; j < sectors; ++j) {
      if (!b.usable[j]) continue;
      const std::size_t base = (s0 + sectors - j) % sectors;
      const double* column_b = b.values.data() + j * rings;
      // Five named sums (not an array) so that they stay in registers.
      Shifts dot0 = {0.0, 0.0, 0.0, 0.0};
      Shifts dot1 = dot0;
      Shifts dot2 = dot0;
      Shifts dot3 = dot0;
      Shifts dot4 = dot0;
      const double* row = a.values.data() + base;
      for (std::size_t i = 0; i < rings; ++i, row += a.width) {
        Shifts a0;
        Shifts a1;
        Shifts a2;
        Shifts a3;
        Shifts a4;
        load(a0, row);
        load(a1, row + kLanes);
        load(a2, row + 2 * kLanes);
        load(a3, row + 3 * kLanes);
        load(a4, row + 4 * kLanes);
        const double value = column_b[i];
        dot0 += a0 * value;
        dot1 += a1 * value;
        dot2 += a2 * value;
        dot3 += a3 * value;
        dot4 += a4 * value;
      }
      const Shifts dots[kGroups] = {dot0, dot1, dot2, dot3, dot4};
      // A column pair that does not qualify adds dot x 0 = +0 (a sum that starts at +0 never
      // becomes -0), so the sum is the scalar one, which skips it.
      for (int g = 0; g < kGroups; ++g) {
        Shifts usable;
        load(usable, a.usable.data() + base + g * kLanes);
        cosine[g] += dots[g] * usable;
        pairs[g] += usable;
      }
    }
    for (int g = 0; g < kGroups; ++g) {
      for (int t = 0; t < kLanes; ++t) {
        const std::size_t s = s0 + static_cast<std::size_t>(g * kLanes + t);
        if (s >= sectors) break;
        cosine_sums[s] = cosine[g][t];
        pair_counts[s] = pairs[g][t];
      }
    }
  }
}

#if RADARPR_COLUMN_ALIGNMENT_X86
// The same code compiled for AVX2 (no FMA: the same roundings), chosen at run time.
__attribute__((target("avx2"))) void shift_sums_avx2(const ReversedColumns& a, const UnitColumns& b,
                                                     std::size_t rings, std::size_t sectors,
                                                     double* cosine_sums, double* pair_counts) {
  shift_sums(a, b, rings, sectors, cosine_sums, pair_counts);
}
#endif

void shift_sums_default(const ReversedColumns& a, const UnitColumns& b, std::size_t rings,
                        std::size_t sectors, double* cosine_sums, double* pair_counts) {
  shift_sums(a, b, rings, sectors, cosine_sums, pair_counts);
}

}  // namespace

std::optional<ColumnAlignment> best_column_alignment(std::span<const float> a,
                                                     std::span<const float> b, int rings,
                                                     int sectors) {
  if (rings < 1 || sectors < 1) {
    throw std::invalid_argument(
        "radar_scan_context: contexts need rings >= 1 and sectors >= 1, got " +
        std::to_string(rings) + " x " + std::to_string(sectors));
  }
  const auto ring_count = static_cast<std::size_t>(rings);
  const auto sector_count = static_cast<std::size_t>(sectors);
  if (a.size() != ring_count * sector_count || b.size() != a.size()) {
    throw std::invalid_argument("radar_scan_context: cannot compare contexts of " +
                                std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                                " values as " + std::to_string(rings) + " x " +
                                std::to_string(sectors));
  }
  // Normalising once per call turns every cosine of the shift loop into a plain dot product.
  const UnitColumns unit_a = unit_columns(a, ring_count, sector_count, "a");
  const UnitColumns unit_b = unit_columns(b, ring_count, sector_count, "b");

  const ReversedColumns reversed = reversed_columns(unit_a, ring_count, sector_count);
  std::vector<double> cosine_sums(sector_count);
  std::vector<double> pair_counts(sector_count);
#if RADARPR_COLUMN_ALIGNMENT_X86
  static const auto shift_sums_here = cpu_features().avx2 ? shift_sums_avx2 : shift_sums_default;
#else
  const auto shift_sums_here = shift_sums_default;
#endif
  shift_sums_here(reversed, unit_b, ring_count, sector_count, cosine_sums.data(),
                  pair_counts.data());
  std::optional<ColumnAlignment> best;
  for (std::size_t s = 0; s < sector_count; ++s) {
    if (pair_counts[s] == 0.0) continue;
    const double similarity = cosine_sums[s] / pair_counts[s];
    if (!best || similarity > best->similarity)
      best = ColumnAlignment{static_cast<int>(s), similarity};
  }
  return best;
}

}  // namespace radarpr
