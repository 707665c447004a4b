// Bilinear lookup in the table of E(NoV, r), the single-scattering specular directional albedo
// with F = 1 (engine/shading/energy_table.cpp integrates it). Shared GLSL / C++: the includer defines
// energyTexel(x, y) (a texelFetch on the GPU, the table itself on the CPU), so both sides
// interpolate with the same arithmetic (texture filtering would round the weights to 8 bits).
const int ENERGY_TABLE_SIZE = 32;   // NoV and r at i / 31, i = 0..31

PATINA_INLINE real energyTableLookup(real NoV, real roughness) {
    TableCoordinate c = tableCoordinate(NoV, roughness, ENERGY_TABLE_SIZE);
    real bottom = mix(energyTexel(c.x0, c.y0), energyTexel(c.x0 + 1, c.y0), c.fx);
    real top = mix(energyTexel(c.x0, c.y0 + 1), energyTexel(c.x0 + 1, c.y0 + 1), c.fx);
    return mix(bottom, top, c.fy);
}
