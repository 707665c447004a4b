#include "views/frame_stats.h"

#include <algorithm>
#include <cstdio>
#include <sys/resource.h>

namespace patina::editor {

std::string frameTimeSummary(std::vector<double> milliseconds) {
    if (milliseconds.empty()) {
        return "0 frames";
    }
    std::sort(milliseconds.begin(), milliseconds.end());
    auto at = [&](double fraction) {
        return milliseconds[std::min(milliseconds.size() - 1, size_t(fraction * double(milliseconds.size())))];
    };
    char text[160];
    std::snprintf(text, sizeof text, "%zu frames, median %.1f ms, p90 %.1f ms, max %.1f ms", milliseconds.size(),
                  at(0.5), at(0.9), milliseconds.back());
    return text;
}

double peakRssMegabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;   // kilobytes on Linux
}

void FrameStats::line(const std::string& text) {
    if (log_) {
        char rss[48];
        std::snprintf(rss, sizeof rss, " (peak RSS %.0f MB)", peakRssMegabytes());
        *log_ << "stats: " << text << rss << std::endl;   // flushed: the log is read live
    }
}

void FrameStats::frameDone(double milliseconds, bool dragging) {
    if (!firstFrameLogged_) {
        firstFrameLogged_ = true;
        const double sinceStart = std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
        char text[96];
        std::snprintf(text, sizeof text, "first frame %.0f ms after start", sinceStart);
        line(text);
        return;
    }
    if (dragging) {
        drag_.push_back(milliseconds);
        return;
    }
    if (!drag_.empty()) {
        line("drag: " + frameTimeSummary(drag_));
        allDrags_.insert(allDrags_.end(), drag_.begin(), drag_.end());
        drag_.clear();
    }
    idle_.push_back(milliseconds);
}

void FrameStats::finish() {
    allDrags_.insert(allDrags_.end(), drag_.begin(), drag_.end());
    drag_.clear();
    line("session: dragging " + frameTimeSummary(allDrags_) + "; other frames " + frameTimeSummary(idle_));
}

}  // namespace patina::editor
