#include "study/study_csv.h"

#include <cstdio>

#include "image/file_io.h"

namespace fp::study {

const char* const kCsvHeader =
    "scene,integrator,denoiser,spp,render_seconds,render_cpu_seconds,denoise_seconds,total_seconds,rmse,rel_"
    "mse,"
    "ssim,flip";

std::string csvText(const std::vector<StudyRow>& rows) {
    std::string text = std::string(kCsvHeader) + "\n";
    for (const StudyRow& r : rows) {
        char line[512];
        std::snprintf(line, sizeof line, "%s,%s,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                      r.scene.c_str(), r.integrator.c_str(), r.denoiser.c_str(), r.spp, r.renderSeconds,
                      r.renderCpuSeconds, r.denoiseSeconds, r.totalSeconds(), r.rmse, r.relMse, r.ssim,
                      r.flip);
        text += line;
    }
    return text;
}

void writeCsv(const std::string& path, const std::vector<StudyRow>& rows) {
    std::string text = csvText(rows);
    writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

}  // namespace fp::study
