#include "study/gpus.h"

#include <algorithm>

namespace fp::study {

const char* gpuClassName(GpuClass c) {
    return c == GpuClass::X80 ? "x80" : "flagship";
}

const char* laneModelName(LaneModel m) {
    switch (m) {
        case LaneModel::Unified:
            return "FP32 or INT32 on every lane";
        case LaneModel::SeparateInt:
            return "separate INT32 lanes";
        case LaneModel::HalfShared:
            return "half the FP32 lanes shared with INT32";
    }
    return "";
}

double fp32Fraction(LaneModel m, double r) {
    r = std::max(r, 0.0);
    switch (m) {
        case LaneModel::Unified:
            return 1.0 / (1.0 + r);
        case LaneModel::SeparateInt:
            return r <= 1.0 ? 1.0 : 1.0 / r;
        case LaneModel::HalfShared:
            return 1.0 / std::max(1.0 + r, 2.0 * r);
    }
    return 1.0;
}

double Gpu::peakTflops() const {
    return fp32Lanes * 2.0 * boostMhz * 1e-6;
}

double gigaRaysPerRtTflops() {
    // NVIDIA's Ampere launch (September 2020) gave the Turing RTX 2080 Super 34 RT TFLOPS (48 SMs, 1815
    // MHz boost); Turing's RT cores are the same in every Turing SM, so the RTX 2080 Ti Founders Edition
    // (68 SMs, 1635 MHz), for which the Turing whitepaper quotes 10 giga rays/s, has 34 x (68 x 1635) /
    // (48 x 1815) = 43.4 RT TFLOPS: 0.230 giga rays per RT TFLOPS. (The RTX 2080 Founders Edition's
    // 8 giga rays/s at 46 SMs and 1800 MHz gives 0.248: NVIDIA's figures are rounded, about 7 % apart.)
    const double rtTflops2080Ti = 34.0 * (68.0 * 1635.0) / (48.0 * 1815.0);
    return 10.0 / rtTflops2080Ti;
}

double Gpu::gigaRays() const {
    if (publishedGigaRays > 0) return publishedGigaRays;
    return rtTflops * gigaRaysPerRtTflops();
}

RaySource Gpu::raySource() const {
    if (publishedGigaRays > 0) return RaySource::Published;
    return rtTflops > 0 ? RaySource::Estimated : RaySource::None;
}

const std::vector<Gpu>& gpuTable() {
    // Lanes and reference boost clocks from NVIDIA's product pages and architecture whitepapers
    // ("NVIDIA GeForce GTX 980 Whitepaper" 2014, "GeForce GTX 1080 Whitepaper" 2016, "NVIDIA Turing GPU
    // Architecture" 2018, "NVIDIA Ampere GA102 GPU Architecture" 2020, "NVIDIA Ada GPU Architecture"
    // 2022, "NVIDIA RTX Blackwell GPU Architecture" 2025); bandwidth = data rate per pin x bus width / 8.
    // The whitepapers themselves are not in this project's reference corpus; the search tool confirmed
    // the figures marked "checked" from launch coverage quoting NVIDIA, the others are from memory of the
    // whitepapers and say so.
    // The flagship class is the fastest GeForce GTX/RTX card on each generation's largest die: the Ti
    // cards until Turing, the x90 cards since Ampere (the 3090 took the Titan's place). Titan-branded
    // cards (Titan X 2015 and 2016, Titan RTX 2018) and the mid-generation 3090 Ti are left out.
    static const std::vector<Gpu> gpus = {
        // 2048 x 1216 MHz = 4.98 TFLOPS; 7 Gbps x 256 bits = 224 GB/s (from memory of the whitepaper).
        {"GTX 980", 2014, GpuClass::X80, "Maxwell", 2048, 1216, 224.0, LaneModel::Unified, 0, 0},
        // 2816 x 1075 MHz = 6.05 TFLOPS; 7 Gbps x 384 bits = 336.5 GB/s (from memory, not checked).
        {"GTX 980 Ti", 2015, GpuClass::Flagship, "Maxwell", 2816, 1075, 336.5, LaneModel::Unified, 0, 0},
        // 2560 x 1733 MHz = 8.87 TFLOPS; 10 Gbps GDDR5X x 256 bits = 320 GB/s (from memory).
        {"GTX 1080", 2016, GpuClass::X80, "Pascal", 2560, 1733, 320.0, LaneModel::Unified, 0, 0},
        // 3584 x 1582 MHz = 11.3 TFLOPS; 11 Gbps x 352 bits = 484 GB/s (from memory, not checked).
        {"GTX 1080 Ti", 2017, GpuClass::Flagship, "Pascal", 3584, 1582, 484.0, LaneModel::Unified, 0, 0},
        // 2944 x 1710 MHz = 10.1 TFLOPS; 14 Gbps x 256 bits = 448 GB/s (checked); Turing whitepaper: 8
        // giga rays/s, quoted for the Founders Edition (1800 MHz boost; 5 % above the reference clock).
        {"RTX 2080", 2018, GpuClass::X80, "Turing", 2944, 1710, 448.0, LaneModel::SeparateInt, 8.0, 0},
        // 4352 x 1545 MHz = 13.4 TFLOPS; 14 Gbps x 352 bits = 616 GB/s; Turing whitepaper and launch: 10
        // giga rays/s (checked: "Turing is capable of 10 gigarays"), Founders Edition (1635 MHz).
        {"RTX 2080 Ti", 2018, GpuClass::Flagship, "Turing", 4352, 1545, 616.0, LaneModel::SeparateInt, 10.0,
         0},
        // 8704 x 1710 MHz = 29.8 TFLOPS; 19 Gbps x 320 bits = 760 GB/s; 58 RT TFLOPS (all checked, NVIDIA
        // launch figures; no giga rays published).
        {"RTX 3080", 2020, GpuClass::X80, "Ampere", 8704, 1710, 760.0, LaneModel::HalfShared, 0, 58.0},
        // 10496 x 1695 MHz = 35.6 TFLOPS; 19.5 Gbps x 384 bits = 936 GB/s; 69 RT TFLOPS (checked).
        {"RTX 3090", 2020, GpuClass::Flagship, "Ampere", 10496, 1695, 936.0, LaneModel::HalfShared, 0, 69.0},
        // 9728 x 2505 MHz = 48.7 TFLOPS; 22.4 Gbps x 256 bits = 716.8 GB/s (checked); 112.7 RT TFLOPS
        // from memory of the Ada whitepaper's table, NOT checked here.
        {"RTX 4080", 2022, GpuClass::X80, "Ada", 9728, 2505, 716.8, LaneModel::HalfShared, 0, 112.7},
        // 16384 x 2520 MHz = 82.6 TFLOPS; 21 Gbps x 384 bits = 1008 GB/s; 191 RT TFLOPS (checked: NVIDIA's
        // "191 effective ray-tracing teraflops").
        {"RTX 4090", 2022, GpuClass::Flagship, "Ada", 16384, 2520, 1008.0, LaneModel::HalfShared, 0, 191.0},
        // 10752 x 2617 MHz = 56.3 TFLOPS; 30 Gbps x 256 bits = 960 GB/s; 171 RT TFLOPS (checked).
        {"RTX 5080", 2025, GpuClass::X80, "Blackwell", 10752, 2617, 960.0, LaneModel::Unified, 0, 171.0},
        // 21760 x 2407 MHz = 104.8 TFLOPS; 28 Gbps x 512 bits = 1792 GB/s; 318 RT TFLOPS (checked).
        {"RTX 5090", 2025, GpuClass::Flagship, "Blackwell", 21760, 2407, 1792.0, LaneModel::Unified, 0,
         318.0},
    };
    return gpus;
}

std::vector<Gpu> gpusOfClass(GpuClass c) {
    std::vector<Gpu> result;
    for (const Gpu& g : gpuTable())
        if (g.gpuClass == c) result.push_back(g);
    return result;
}

}  // namespace fp::study
