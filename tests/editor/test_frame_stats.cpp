// `patina --stats`: the summaries it logs, without a window.
#include <sstream>

#include <gtest/gtest.h>

#include "views/frame_stats.h"

namespace patina::editor {
namespace {

TEST(FrameStats, SummaryGivesMedianP90AndMax) {
    std::vector<double> times;
    for (int i = 10; i >= 1; --i) {
        times.push_back(double(i));   // unsorted on purpose
    }
    EXPECT_EQ(frameTimeSummary(times), "10 frames, median 6.0 ms, p90 10.0 ms, max 10.0 ms");
    EXPECT_EQ(frameTimeSummary({}), "0 frames");
}

TEST(FrameStats, LogsTheFirstFrameAndEachDragWhenItEnds) {
    std::ostringstream log;
    FrameStats stats(&log, FrameStats::Clock::now());
    stats.frameDone(50.0, false);
    EXPECT_NE(log.str().find("stats: first frame "), std::string::npos);
    EXPECT_NE(log.str().find("MB)"), std::string::npos);
    for (double ms : {4.0, 8.0, 6.0}) {
        stats.frameDone(ms, true);
    }
    EXPECT_EQ(log.str().find("drag:"), std::string::npos) << "logged before the drag ended";
    stats.frameDone(1.0, false);
    EXPECT_NE(log.str().find("stats: drag: 3 frames, median 6.0 ms, p90 8.0 ms, max 8.0 ms"), std::string::npos)
        << log.str();
    stats.finish();
    EXPECT_NE(log.str().find("session: dragging 3 frames"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace patina::editor
