#pragma once
// The inputs where the formulas fail (docs/SHADING.md S2), as probe
// rows and scenes, for the CPU and GPU edge sweeps.
#include <string>
#include <vector>

#include "scene/probe.h"
#include "scene/scene.h"

namespace patina {

struct EdgeCase {
    std::string name;
    Material material;
    std::vector<Light> lights;
    std::vector<ProbeSample> samples;
};

std::vector<EdgeCase> edgeCases();
// Sphere and tube lights (Karis 2013, "Area lights") at the sizes and places where the
// representative point, the widening or the horizon clipping divide by 0 or leave their domain:
// a radius above the range, radius 0, a tube of length 0 (and one just longer), the point inside
// the light or on its centre, a light behind or through the surface. Each at roughness 0 and
// 0.5, seen from straight above and at grazing, and with a zero normal.
std::vector<EdgeCase> areaLightEdgeCases();

}  // namespace patina
