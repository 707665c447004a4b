// GPU side of image-based lighting (shaders/shared/ibl.glsl, ibl_model.glsl): the prefiltered
// chain and the irradiance map as cube maps (GL_TEXTURE_CUBE_MAP_SEAMLESS on), the model's
// (A, B) table read texel by texel as energy_texel.glsl reads E, and the light's uniforms.
// Include before ibl.glsl.
#define EnvironmentSource samplerCube
#define sampleEnvironmentSource(source, direction, lod) textureLod(source, direction, lod).rgb

uniform samplerCube uEnvironmentMap;
uniform float uEnvironmentMaxLod;
uniform float uEnvironmentIntensity;
uniform vec2 uEnvironmentRotation;   // cos, sin of rotationDegrees
uniform samplerCube uEnvironmentIrradiance;   // the irradiance map (environment/irradiance.h)
uniform sampler2D uEnvironmentBrdf;
// The stochastic mode's source: the unfiltered cube and its box-filtered mips, faces of
// uEnvironmentSourceSize texels.
uniform samplerCube uEnvironmentSource;
uniform float uEnvironmentSourceSize;

vec2 environmentBrdfTexel(int x, int y) {
    return texelFetch(uEnvironmentBrdf, ivec2(x, y), 0).rg;
}
