#pragma once
// The peak FP32 rate of the CPU the study runs on, from /proc/cpuinfo, to turn measured throughput
// into an efficiency:
//   peak = physical cores x clock x (SIMD width / 32 bits) x FMA pipes x 2 FLOPs per FMA.
// The SIMD width is the widest the CPU flags allow (avx512f 512, avx/avx2 256, sse 128), capped by
// the vector width llvmpipe compiles to (its GL_RENDERER string says "256 bits"). /proc/cpuinfo does
// not tell the number of FMA pipes; 2 per core is assumed (true of Intel since Haswell and AMD since
// Zen 2; a CPU with AVX-512 on two 256-bit pipes, as Zen 4, has the same FP32 rate as with 256 bits).
#include <string>

namespace fp::study {

struct CpuPeak {
    std::string model;
    int cores = 0;     // physical: "cpu cores" x sockets, else the logical CPUs
    double ghz = 0.0;  // the cpufreq maximum if given, else /proc/cpuinfo's "cpu MHz"
    int simdBits = 0;
    bool fma = false;  // without FMA: one add and one multiply pipe, 2 FLOPs per lane per cycle
    int fmaPipes = 2;
    double flopsPerLanePerCycle() const { return fma ? fmaPipes * 2.0 : 2.0; }
    double gflops() const { return cores * ghz * (simdBits / 32.0) * flopsPerLanePerCycle(); }
    std::string formula() const;  // "2 cores x 2.6 GHz x 8 lanes x 2 FMA pipes x 2 = 166 GFLOPS"
};

// From the text of /proc/cpuinfo; maxMhz (0: unknown) from cpufreq; rendererVectorBits (0: unknown)
// from the GL renderer string. Throws fp::Error if the text has no processor or no clock.
CpuPeak parseCpuPeak(const std::string& cpuinfo, double maxMhz, int rendererVectorBits);
// This machine's, reading /proc/cpuinfo and /sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq.
CpuPeak thisMachinePeak(const std::string& glRenderer);
// "llvmpipe (LLVM 15.0.6, 256 bits)" -> 256; 0 if the string names no width.
int rendererVectorBits(const std::string& glRenderer);

}  // namespace fp::study
