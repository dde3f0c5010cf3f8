#include "viewer/frame_stats.h"

#include "core/statistics.h"

namespace fp {

void FrameStats::addFrame(double now, double frameSeconds, double paths, double imagePixels) {
    imagePixels_ = imagePixels;
    recent_.push_back({now, frameSeconds, paths});
    while (recent_.size() > 1 && now - recent_.front().end > window_) recent_.pop_front();
    if (!all_.empty()) steadyPaths_ += paths, steadySeconds_ += frameSeconds;
    all_.push_back(frameSeconds);
}

double FrameStats::frameSeconds() const {
    if (recent_.empty()) return 0.0;
    double total = 0.0;
    for (const Frame& f : recent_) total += f.seconds;
    return total / double(recent_.size());
}

double FrameStats::pathsPerSecond() const {
    double seconds = 0.0, paths = 0.0;
    for (const Frame& f : recent_) seconds += f.seconds, paths += f.paths;
    return seconds > 0.0 ? paths / seconds : 0.0;
}

double FrameStats::medianFrameSeconds() const {
    return all_.empty() ? 0.0 : median(all_);
}

}  // namespace fp
