#pragma once
// The BRDF-only floor of bench-render: the specialised path with light code of the bench's own,
// every light as a direction with the BRDF and cosine alone (no type, no attenuation, no
// branch): the arithmetic floor of a light's cost. The renderer knows nothing of it.
#include <vector>

#include "gl/renderer.h"
#include "scene/scene.h"

namespace patina {

// The floor's light code for `count` lights, read the same way as specialiseFor would read
// them (the first `flatSlots` as flat inputs).
ShaderSpecialisation brdfFloorFor(size_t count, size_t flatSlots);
// The same lights as directions only: the floor's scene, so that every path shades like lights.
Scene brdfFloorScene(const Scene& scene);
// Settings that draw the floor: specialised, with brdfFloorFor as the light code.
RenderSettings brdfFloorSettings(RenderSettings settings);

}  // namespace patina
