// GPU side of sheen.glsl's sheenTexel: E(N.V, r) of the sheen lobe as an R32F texture
// (engine/shading/sheen_table.cpp), read only by a program with PATINA_SHEEN.
uniform sampler2D uSheenTable;

float sheenTexel(int x, int y) {
    return texelFetch(uSheenTable, ivec2(x, y), 0).r;
}
