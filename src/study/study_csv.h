#pragma once
// study.csv: one row per scene x integrator x denoiser x samples per pixel (columns in README.md, "Study").
#include <string>
#include <vector>

#include "study/sweep.h"

namespace fp::study {

// The header line, without its newline.
extern const char* const kCsvHeader;

std::string csvText(const std::vector<StudyRow>& rows);
// Writes atomically (image/file_io.h); throws fp::Error naming the path.
void writeCsv(const std::string& path, const std::vector<StudyRow>& rows);

}  // namespace fp::study
