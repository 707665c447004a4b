// Bilinear lookup in the table of E(NoV, r), the single-scattering specular directional albedo
// with F = 1 (engine/shading/energy_table.cpp integrates it). Shared GLSL / C++: the includer defines
// energyTexel(x, y) (a texelFetch on the GPU, the table itself on the CPU), so both sides
// interpolate with the same arithmetic (texture filtering would round the weights to 8 bits).
const int ENERGY_TABLE_SIZE = 32;   // NoV and r at i / 31, i = 0..31

// Where (NoV, r) falls in a table of `size` x `size` values at i / (size - 1): the lower
// texel and the weights of the next, for the tables' own bilinear lookups (this one and
// ibl_model.glsl's environment BRDF).
struct TableCoordinate {
    int x0;
    int y0;
    real fx;
    real fy;
};

PATINA_INLINE TableCoordinate tableCoordinate(real NoV, real roughness, int size) {
    real x = clamp(NoV, 0.0f, 1.0f) * real(size - 1);
    real y = clamp(roughness, 0.0f, 1.0f) * real(size - 1);
    int x0 = min(int(x), size - 2);
    int y0 = min(int(y), size - 2);
    return TableCoordinate(x0, y0, x - real(x0), y - real(y0));
}

PATINA_INLINE real energyTableLookup(real NoV, real roughness) {
    TableCoordinate c = tableCoordinate(NoV, roughness, ENERGY_TABLE_SIZE);
    real bottom = mix(energyTexel(c.x0, c.y0), energyTexel(c.x0 + 1, c.y0), c.fx);
    real top = mix(energyTexel(c.x0, c.y0 + 1), energyTexel(c.x0 + 1, c.y0 + 1), c.fx);
    return mix(bottom, top, c.fy);
}
