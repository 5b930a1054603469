#pragma once

namespace radarpr {

// The x86 instruction sets the fast paths choose between at run time, as this processor and its
// operating system support them (AVX and AVX-512 only where the system saves their registers).
// All false on other processors.
//
// Why not __builtin_cpu_supports: linking it brings libgcc's __cpu_indicator_init, a constructor
// that asks the processor about every feature GCC knows when the program starts, and in a virtual
// machine each cpuid instruction traps to the hypervisor (about 4 us here): every radarpr process
// paid some 60 us for it, `radarpr --version` included. This asks only what radarpr uses, the
// first time a fast path wants to know.
struct CpuFeatures {
  bool popcnt = false;
  bool fma = false;
  bool avx2 = false;
  bool avx512f = false;
  bool avx512bw = false;
  bool avx512vl = false;
  bool avx512vnni = false;
};

// Probed once (thread-safe), on the first call.
const CpuFeatures& cpu_features();

}  // namespace radarpr
