#pragma once
#include "environment/prefilter.h"

namespace patina {

// prefilterCube (environment/prefilter.h) on the GPU: each face of each level drawn by
// shaders/stages/prefilter.frag, which runs the same prefilterEnvironment as the CPU, reading
// `source` through the GPU's trilinear seamless filter; read back as a CubeChain. Needs a
// current context; `progress` is told after each face. Empty when it stopped the work.
CubeChain prefilterCubeOnGpu(const CubeChain& source, const PrefilterSettings& settings, const Progress& progress = {});

}  // namespace patina
