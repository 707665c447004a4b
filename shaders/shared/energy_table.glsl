// Bilinear lookup in the table of E(NoV, r), the single-scattering specular directional albedo
// with F = 1 (engine/shading/energy_table.cpp integrates it). Shared GLSL / C++: the includer defines
// energyTexel(x, y) (a texelFetch on the GPU, the table itself on the CPU), so both sides
// interpolate with the same arithmetic (texture filtering would round the weights to 8 bits).
const int ENERGY_TABLE_SIZE = 32;   // NoV and r at i / 31, i = 0..31

PATINA_INLINE real energyTableLookup(real NoV, real roughness) {
    real x = clamp(NoV, 0.0f, 1.0f) * real(ENERGY_TABLE_SIZE - 1);
    real y = clamp(roughness, 0.0f, 1.0f) * real(ENERGY_TABLE_SIZE - 1);
    int x0 = min(int(x), ENERGY_TABLE_SIZE - 2);
    int y0 = min(int(y), ENERGY_TABLE_SIZE - 2);
    real fx = x - real(x0);
    real fy = y - real(y0);
    real bottom = mix(energyTexel(x0, y0), energyTexel(x0 + 1, y0), fx);
    real top = mix(energyTexel(x0, y0 + 1), energyTexel(x0 + 1, y0 + 1), fx);
    return mix(bottom, top, fy);
}
