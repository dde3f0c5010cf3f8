#pragma once
// report.md's "The seed's claim, in both senses": was real-time path tracing (1920x1080 at 60 fps)
// possible within four years of 2016, i.e. by 2020, (a) with every frame alone under the study's
// threshold, and (b) as practice does it, with few samples per frame, temporal reuse and a denoiser?
// Each answer names the first GPU of each class (roofline.h firstReaching) and its year.
#include <optional>
#include <string>

#include "study/report.h"
#include "study/roofline.h"

namespace fp::study {

constexpr int kSeedYear = 2016;
constexpr int kSeedHorizonYears = 4;

// One criterion's answer: the samples per frame, the paths per second 1080p60 needs at them, and the
// first GPU of each class at 100% of every limit and with FP32 at the measured efficiency.
struct SeedAnswer {
    std::string integrator, denoiser;
    double spp = 0.0, pathsPerSecond = 0.0, efficiency = 1.0;
    ClassAnswer x80, flagship, x80Measured, flagshipMeasured;
    std::string binding;  // the limit that binds on gpu(), at 100% of every limit (roofline.h limitName)
    // The earlier of the two classes' first GPUs at 100% of every limit.
    std::optional<int> year() const;
    std::string gpu() const;
    bool heldBy(int year) const { return this->year() && *this->year() <= year; }
};

// (a): of the feasibility rows that reach the threshold, the one whose first GPU comes earliest (the
// fewer samples on a tie); nothing if none reaches it.
std::optional<SeedAnswer> convergedAnswer(const ReportInput& input);
// (b): `spp` samples per frame of `integrator`'s paths; nothing without that integrator's path counts.
std::optional<SeedAnswer> practiceAnswer(const ReportInput& input, const std::string& integrator, double spp);

std::string seedClaimMarkdown(const ReportInput& input);

}  // namespace fp::study
