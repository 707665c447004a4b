#include "shading/environment_brdf.h"

#include <algorithm>
#include <array>
#include <mutex>

#include "common/parallel_for.h"
#include "shading/brdf_models.h"

// integrateEnvironmentBrdf and the other per-model functions dispatch in brdf_models.cpp, where
// the models' permutations are compiled.
namespace patina {

std::vector<glm::vec2> integrateEnvironmentBrdfTable(BrdfModelId id, int size, unsigned samples) {
    // A row a task on every core: each texel is its own integral, so the table is the same
    // whatever the order (a process's first environment used to wait ~0.1 s for it here).
    std::vector<glm::vec2> table(size_t(size) * size_t(size));
    parallelFor(size_t(std::max(size, 0)), [&](size_t row) {
        const int y = int(row);
        for (int x = 0; x < size; ++x) {
            const float NoV = float(x) / float(size - 1), r = float(y) / float(size - 1);
            table[size_t(y) * size_t(size) + size_t(x)] = integrateEnvironmentBrdf(id, NoV, r, samples);
        }
    });
    return table;
}

const std::vector<glm::vec2>& environmentBrdfTable(BrdfModelId id) {
    static std::array<std::once_flag, brdfModelCount()> once;
    static std::array<std::vector<glm::vec2>, brdfModelCount()> tables;
    const size_t index = size_t(id);
    std::call_once(once[index], [&] {
        tables[index] = integrateEnvironmentBrdfTable(id, kEnvironmentBrdfSize, kEnvironmentBrdfSamples);
    });
    return tables[index];
}

}  // namespace patina
