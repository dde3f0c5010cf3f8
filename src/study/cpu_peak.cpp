#include "study/cpu_peak.h"

#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"

namespace fp::study {

namespace {

// The value of the first "key : value" line with this key.
std::string field(const std::string& cpuinfo, const std::string& key) {
    std::istringstream lines(cpuinfo);
    std::string line;
    while (std::getline(lines, line)) {
        size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string name = line.substr(0, colon);
        while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
        if (name != key) continue;
        size_t start = line.find_first_not_of(' ', colon + 1);
        return start == std::string::npos ? "" : line.substr(start);
    }
    return "";
}

bool hasFlag(const std::string& flags, const std::string& flag) {
    std::istringstream words(flags);
    std::string word;
    while (words >> word)
        if (word == flag) return true;
    return false;
}

}  // namespace

std::string CpuPeak::formula() const {
    char text[256];
    if (fma)
        std::snprintf(text, sizeof text,
                      "%d cores x %.4g GHz x %d FP32 lanes x %d FMA pipes x 2 FLOPs = %.4g GFLOPS", cores,
                      ghz, simdBits / 32, fmaPipes, gflops());
    else
        std::snprintf(text, sizeof text,
                      "%d cores x %.4g GHz x %d FP32 lanes x (1 add + 1 mul) = %.4g GFLOPS", cores, ghz,
                      simdBits / 32, gflops());
    return text;
}

int rendererVectorBits(const std::string& glRenderer) {
    std::smatch m;
    if (std::regex_search(glRenderer, m, std::regex("(\\d+) bits"))) return std::stoi(m[1]);
    return 0;
}

CpuPeak parseCpuPeak(const std::string& cpuinfo, double maxMhz, int vectorBits) {
    CpuPeak peak;
    std::istringstream lines(cpuinfo);
    std::string line;
    int logical = 0;
    std::set<std::string> sockets;
    while (std::getline(lines, line)) {
        if (line.rfind("processor", 0) == 0) ++logical;
        if (line.rfind("physical id", 0) == 0) sockets.insert(line);
    }
    if (logical == 0) throw Error("/proc/cpuinfo lists no processor");
    peak.model = field(cpuinfo, "model name");
    std::string coresText = field(cpuinfo, "cpu cores");
    peak.cores = coresText.empty() ? logical : std::stoi(coresText) * std::max<int>(1, int(sockets.size()));
    std::string mhz = field(cpuinfo, "cpu MHz");
    double mhzValue = maxMhz > 0 ? maxMhz : mhz.empty() ? 0.0 : std::stod(mhz);
    if (!(mhzValue > 0)) throw Error("/proc/cpuinfo gives no clock rate");
    peak.ghz = mhzValue / 1000.0;
    std::string flags = field(cpuinfo, "flags");
    peak.simdBits = hasFlag(flags, "avx512f") ? 512 : hasFlag(flags, "avx") ? 256 : 128;
    if (vectorBits > 0) peak.simdBits = std::min(peak.simdBits, vectorBits);
    peak.fma = hasFlag(flags, "fma");
    return peak;
}

CpuPeak thisMachinePeak(const std::string& glRenderer) {
    std::ifstream in("/proc/cpuinfo");
    std::stringstream text;
    text << in.rdbuf();
    double maxMhz = 0.0;
    std::ifstream freq("/sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq");  // kHz
    if (double khz = 0; freq >> khz) maxMhz = khz / 1000.0;
    return parseCpuPeak(text.str(), maxMhz, rendererVectorBits(glRenderer));
}

}  // namespace fp::study
