#include "reference/surface_maps.h"

#include <cmath>

#include "shading/shading.h"
#include "shading/texture_sampling.h"

namespace patina {

MapTextures::MapTextures(const Model& model) {
    for (const ModelMaterial& material : model.materials) {
        for (const auto& [slot, srgb, name, key] : mapsOf(material)) {
            const bool usable = slot->present() && size_t(slot->image) < model.images.size() &&
                                !model.images[size_t(slot->image)].rgba.empty();
            if (usable && !textures_.count({slot->image, srgb})) {
                const ModelImage& image = model.images[size_t(slot->image)];
                std::vector<LinearTexture>& levels = textures_[{slot->image, srgb}];
                levels.push_back(linearTexture(image.rgba.data(), image.width, image.height, srgb));
                for (const ImageLevel& level : mipLevels(image.rgba.data(), image.width, image.height, srgb)) {
                    levels.push_back(linearTexture(level.rgba.data(), level.width, level.height, srgb));
                }
            }
        }
    }
}

glm::vec4 MapTextures::texel(const TextureSlot& slot, bool srgb, const MapCoordinates& at, glm::vec4 absent) const {
    const auto found = textures_.find({slot.image, srgb});
    if (!slot.present() || found == textures_.end()) {
        return absent;
    }
    const bool second = slot.texCoord == 1;
    // The transform is affine: its offset moves no derivative.
    auto moved = [&](glm::vec2 d) {
        return shader::transformTextureCoordinate(d, glm::vec2(0.0f), slot.transform.scale, slot.transform.rotation);
    };
    const LinearTexture& base = found->second.front();
    const float lod = shader::textureLevelOfDetail(moved(second ? at.uv1Dx : at.uv0Dx), moved(second ? at.uv1Dy : at.uv0Dy),
                                                   glm::vec2(float(base.width), float(base.height)));
    return sampleTextureLod(found->second, slot.sampler, transformedUv(slot.transform, second ? at.uv1 : at.uv0), lod);
}

bool keptByMask(const SceneDraw& draw, const MapTextures& textures, const MapCoordinates& at) {
    if (draw.alphaCutoff < 0.0f || !draw.maps) {
        return true;   // a MASK item without maps was kept or dropped whole (sceneDraws)
    }
    const float alpha =
        draw.maps->baseAlpha * at.color.a * textures.texel(draw.maps->baseColor, true, at, glm::vec4(1.0f)).w;
    return alpha >= draw.alphaCutoff;
}

MappedSurface mappedSurface(const SceneDraw& draw, const MapTextures& textures, const MapCoordinates& at,
                            glm::vec3 normal) {
    MappedSurface surface;
    surface.material = draw.material;
    surface.normal = normal;
    const ModelMaterial* maps = draw.maps;
    if (!maps) {
        return surface;
    }
    auto texel = [&](const TextureSlot& slot, bool srgb, glm::vec4 absent) {
        return textures.texel(slot, srgb, at, absent);
    };
    const shader::TexturedMaterial mapped = shader::texturedMaterial(
        glm::vec4(draw.material.baseColor, maps->baseAlpha) * at.color, texel(maps->baseColor, true, glm::vec4(1.0f)),
        draw.material.roughness, draw.material.metallic, texel(maps->metallicRoughness, false, glm::vec4(1.0f)));
    surface.material.baseColor = mapped.baseColor;
    surface.material.roughness = mapped.roughness;
    surface.material.metallic = mapped.metallic;
    surface.alpha = mapped.alpha;
    // KHR_materials_clearcoat's factor maps: R scales the coat, G its roughness (the coat's
    // normal map is the GPU's alone: the ground truth lays the coat on the shading normal).
    surface.material.clearcoat *= texel(maps->clearcoat, false, glm::vec4(1.0f)).x;
    surface.material.clearcoatRoughness *= texel(maps->clearcoatRoughness, false, glm::vec4(1.0f)).y;
    // KHR_materials_sheen's: RGB (sRGB) scales the sheen's colour, A its roughness.
    surface.material.sheenColor *= glm::vec3(texel(maps->sheenColor, true, glm::vec4(1.0f)));
    surface.material.sheenRoughness *= texel(maps->sheenRoughness, false, glm::vec4(1.0f)).w;
    // KHR_materials_transmission's: R scales the factor; KHR_materials_volume's: G the thickness.
    surface.material.transmission *= texel(maps->transmissionMap, false, glm::vec4(1.0f)).x;
    surface.material.thickness *= texel(maps->thicknessMap, false, glm::vec4(1.0f)).y;
    // KHR_materials_specular's: RGB (sRGB) scales the tint, A the weight.
    surface.material.specularTint *= glm::vec3(texel(maps->specularColor, true, glm::vec4(1.0f)));
    surface.material.specularWeight *= texel(maps->specular, false, glm::vec4(1.0f)).w;
    // KHR_materials_anisotropy's: RG a direction in the tangent frame (texel (1, 0.5): none),
    // added to the rotation as its angle; B scales the strength (surface_maps.glsl's).
    if (maps->anisotropyMap.present()) {
        const glm::vec4 a = texel(maps->anisotropyMap, false, glm::vec4(1.0f, 0.5f, 1.0f, 1.0f));
        const glm::vec2 d(2.0f * a.x - 1.0f, 2.0f * a.y - 1.0f);
        if (glm::dot(d, d) > 1e-12f) {
            surface.material.anisotropyRotation += std::atan2(d.y, d.x);
        }
        surface.material.anisotropyStrength *= a.z;
    }
    // KHR_materials_iridescence's: R scales the strength; G places the thickness between the
    // minimum and maximum, kept in the maximum (cpu_shading.cpp's surfaceMaterial reads it there).
    surface.material.iridescence *= texel(maps->iridescenceMap, false, glm::vec4(1.0f)).x;
    if (maps->iridescenceThickness.present()) {
        const float g = texel(maps->iridescenceThickness, false, glm::vec4(1.0f)).y;
        surface.material.iridescenceThicknessMaximum =
            glm::mix(draw.material.iridescenceThicknessMinimum, draw.material.iridescenceThicknessMaximum, g);
    }
    if (maps->normal.present()) {
        const glm::vec4 n = texel(maps->normal, false, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
        surface.normal =
            shader::normalMappedNormal(normal, at.tangent, shader::tangentSpaceNormal(glm::vec3(n), maps->normalScale));
    }
    if (maps->occlusion.present()) {
        surface.occlusion = shader::occlusionFactor(texel(maps->occlusion, false, glm::vec4(1.0f)).x,
                                                    maps->occlusionStrength);
    }
    surface.emission = maps->emissiveFactor * glm::vec3(texel(maps->emissive, true, glm::vec4(1.0f)));
    return surface;
}

}  // namespace patina
