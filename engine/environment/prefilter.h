#pragma once
#include "common/progress.h"
#include "environment/cube_map.h"

namespace patina {

struct PrefilterSettings {
    int levels = 6;          // mips of the prefiltered chain, r = 0 to 1 (fewer for a small source)
    unsigned samples = 128;  // GGX samples per texel, read with filtered importance sampling
    bool operator==(const PrefilterSettings&) const = default;
};

// The prefiltered chain of Karis's split sum: level i holds LD for r = lodToRoughness(i, last)
// (shaders/shared/ibl.glsl), level 0 the source's mip 0 itself (r = 0 is a mirror), each level
// half the size of the one before. `source` is the full mip chain FIS reads. On every core;
// empty when `progress` stopped it.
CubeChain prefilterCube(const CubeChain& source, const PrefilterSettings& settings, const Progress& progress = {});

// Where an environment's prefilter runs: prefilterCube (the CPU, needs nothing) or the GPU's pass
// (gl/gpu_prefilter.h, needs a GL context current on the calling thread). The caller that makes
// an environment says which, through prepareEnvironment, makeEnvironment, AssetCache and
// prepareScene.
using PrefilterFunction = CubeChain (*)(const CubeChain&, const PrefilterSettings&, const Progress&);

// How many levels the chain of a source of `faceSize` texels has: settings.levels, fewer when
// the faces run out of texels (each level halves them, down to 1).
int prefilterLevelCount(int faceSize, const PrefilterSettings& settings);

}  // namespace patina
