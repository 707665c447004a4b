#pragma once
// `patina --stats`: what the editor costs the artist, logged as it happens: time from start to
// the first frame, then frame times during each drag (slider or viewport) and the process's
// peak memory. One line per event, so a script can follow the log live.
#include <chrono>
#include <ostream>
#include <string>
#include <vector>

namespace patina::editor {

// "N frames, median M ms, p90 P ms, max X ms" of frame times in milliseconds.
std::string frameTimeSummary(std::vector<double> milliseconds);

class FrameStats {
public:
    using Clock = std::chrono::steady_clock;
    // log: where lines go (nullptr: off); start: when the process began.
    FrameStats(std::ostream* log, Clock::time_point start) : log_(log), start_(start) {}

    // After each frame is on screen: its time from input to swap, and whether a widget was
    // being dragged during it. A drag's summary is logged when it ends.
    void frameDone(double milliseconds, bool dragging);
    // The whole session's summary (on exit).
    void finish();

private:
    std::ostream* log_;
    Clock::time_point start_;
    bool firstFrameLogged_ = false;
    std::vector<double> drag_, allDrags_, idle_;

    void line(const std::string& text);
};

// Peak resident memory of this process in MB (getrusage).
double peakRssMegabytes();

}  // namespace patina::editor
