// GPU side of energy_table.glsl's energyTexel: the model's E(NoV, r) table as an R32F texture.
uniform sampler2D uEnergyTable;

float energyTexel(int x, int y) {
    return texelFetch(uEnergyTable, ivec2(x, y), 0).r;
}
