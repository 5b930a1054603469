#include "datasets/cpu_features.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#define RADARPR_CPUID_X86 1
#endif

namespace radarpr {
namespace {

#if defined(RADARPR_CPUID_X86)

// XCR0, the register states the operating system saves on a context switch (xgetbv is valid
// only when cpuid says OSXSAVE).
unsigned long long saved_states() {
  unsigned low = 0;
  unsigned high = 0;
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (static_cast<unsigned long long>(high) << 32) | low;
}

CpuFeatures probe() {
  // The same rules as GCC's __builtin_cpu_supports: AVX, AVX2 and FMA need the SSE and AVX
  // register states saved, AVX-512 also its mask and upper register states.
  constexpr unsigned long long kAvxStates = 0x6;      // SSE, AVX
  constexpr unsigned long long kAvx512States = 0xe6;  // and opmask, ZMM_Hi256, Hi16_ZMM
  CpuFeatures found;
  // Three cpuid instructions: the highest leaf once (__get_cpuid would ask it again per leaf),
  // then leaves 1 and 7.
  const unsigned highest_leaf = __get_cpuid_max(0, nullptr);
  if (highest_leaf < 1) return found;
  unsigned eax = 0;
  unsigned ebx = 0;
  unsigned ecx = 0;
  unsigned edx = 0;
  __cpuid(1, eax, ebx, ecx, edx);
  found.popcnt = (ecx & bit_POPCNT) != 0;
  const unsigned long long states = (ecx & bit_OSXSAVE) != 0 ? saved_states() : 0;
  const bool avx_usable = (states & kAvxStates) == kAvxStates && (ecx & bit_AVX) != 0;
  const bool avx512_usable = (states & kAvx512States) == kAvx512States;
  found.fma = avx_usable && (ecx & bit_FMA) != 0;
  if (highest_leaf < 7) return found;
  __cpuid_count(7, 0, eax, ebx, ecx, edx);
  found.avx2 = avx_usable && (ebx & bit_AVX2) != 0;
  found.avx512f = avx512_usable && (ebx & bit_AVX512F) != 0;
  found.avx512bw = avx512_usable && (ebx & bit_AVX512BW) != 0;
  found.avx512vl = avx512_usable && (ebx & bit_AVX512VL) != 0;
  found.avx512vnni = avx512_usable && (ecx & bit_AVX512VNNI) != 0;
  return found;
}

#else

CpuFeatures probe() {
  return {};
}

#endif

}  // namespace

const CpuFeatures& cpu_features() {
  static const CpuFeatures features = probe();
  return features;
}

}  // namespace radarpr
