#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

#include "core/clock.h"

namespace fp {

Progress::Progress(int total)
    : total_(total), enabled_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

void Progress::update(int done) {
    if (!enabled_ || total_ <= 0) return;
    double elapsed = secondsSince(start_);
    double fraction = double(done) / double(total_);
    double eta = done > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 30;
    int filled = int(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\r[%s] %d/%d spp  %.1fs elapsed, ETA %.1fs ", bar, done, total_, elapsed, eta);
    std::fflush(stderr);
}

void Progress::finish() {
    if (enabled_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace fp
