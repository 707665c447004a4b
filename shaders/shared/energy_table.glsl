// Bilinear lookup in the table of E(NoV, r), the single-scattering specular directional albedo
// with F = 1 (engine/shading/energy_table.cpp integrates it). Shared GLSL / C++: the includer defines
// energyTexel(x, y) (a texelFetch on the GPU, the table itself on the CPU), so both sides
// interpolate with the same arithmetic (texture filtering would round the weights to 8 bits).
const int ENERGY_TABLE_SIZE = 32;   // NoV and r at i / 31, i = 0..31

PATINA_INLINE float energyTableLookup(float NoV, float roughness) {
    float x = clamp(NoV, 0.0f, 1.0f) * float(ENERGY_TABLE_SIZE - 1);
    float y = clamp(roughness, 0.0f, 1.0f) * float(ENERGY_TABLE_SIZE - 1);
    int x0 = min(int(x), ENERGY_TABLE_SIZE - 2);
    int y0 = min(int(y), ENERGY_TABLE_SIZE - 2);
    float fx = x - float(x0);
    float fy = y - float(y0);
    float bottom = mix(energyTexel(x0, y0), energyTexel(x0 + 1, y0), fx);
    float top = mix(energyTexel(x0, y0 + 1), energyTexel(x0 + 1, y0 + 1), fx);
    return mix(bottom, top, fy);
}
