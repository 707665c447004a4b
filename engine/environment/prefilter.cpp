#include "environment/prefilter.h"

#include <algorithm>
#include <atomic>
#include <vector>

#include "common/parallel_for.h"
#include "shading/shading.h"

namespace patina {

int prefilterLevelCount(int faceSize, const PrefilterSettings& settings) {
    int levels = 1;
    while (levels < settings.levels && (faceSize >> levels) >= 1) {
        ++levels;
    }
    return levels;
}

CubeChain prefilterCube(const CubeChain& source, const PrefilterSettings& settings, const Progress& progress) {
    const int base = source.front().size;
    const int levels = prefilterLevelCount(base, settings);
    const float maxLod = float(levels - 1);
    CubeChain chain;
    chain.push_back(source.front());
    for (int i = 1; i < levels; ++i) {
        chain.emplace_back(base >> i);
    }
    // One job a row of a face of a level; rows of the smaller levels are cheaper, but there are
    // enough of them that the cores stay busy to the end.
    struct Row {
        int level, face, t;
    };
    std::vector<Row> rows;
    for (int level = 1; level < levels; ++level) {
        for (int face = 0; face < 6; ++face) {
            for (int t = 0; t < chain[size_t(level)].size; ++t) {
                rows.push_back({level, face, t});
            }
        }
    }
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(source, d, lod);
    };
    std::atomic<size_t> done{0};
    std::atomic<bool> stopped{false};
    parallelFor(rows.size(), [&](size_t job) {
        if (stopped) {
            return;   // the rest are skipped
        }
        const Row& row = rows[job];
        CubeLevel& level = chain[size_t(row.level)];
        const float roughness = shader::lodToRoughness(float(row.level), maxLod);
        for (int s = 0; s < level.size; ++s) {
            const glm::vec3 R = cubeTexelDirection(row.face, s, row.t, level.size);
            level.setTexel(row.face, s, row.t,
                           shader::prefilterEnvironment(read, R, roughness, settings.samples, float(base)));
        }
        const size_t finished = ++done;
        if (progress && finished % 64 == 0 && !progress(float(finished) / float(rows.size()))) {
            stopped = true;
        }
    });
    if (stopped) {
        return {};
    }
    return chain;
}

}  // namespace patina
