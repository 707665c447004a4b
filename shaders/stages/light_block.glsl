// The lights of a scene as the renderer uploads them (engine/gl/shading_inputs.cpp): read by
// shade.frag, and by mesh.vert when a specialised shader takes lights as flat inputs.
layout(std140) uniform LightBlock {
    PackedLight uLights[MAX_LIGHTS];
    ivec4 uLightCount;       // all, points, directionals, hemispheres
    ivec4 uAreaLightCount;   // spheres, tubes, 0, 0
};
