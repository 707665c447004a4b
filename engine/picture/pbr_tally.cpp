#include "picture/pbr_tally.h"

#include "shading/shading.h"

namespace patina {

PbrVerdict pbrVerdictOfShown(const uint8_t* rgba) {
    const auto shows = [rgba](int verdict) {
        const glm::vec3 colour = shader::pbrVerdictColour(verdict);
        return rgba[0] == uint8_t(255.0f * colour.r) && rgba[1] == uint8_t(255.0f * colour.g) &&
               rgba[2] == uint8_t(255.0f * colour.b);
    };
    return shows(shader::PBR_DIELECTRIC_TOO_DARK)     ? PbrVerdict::DielectricTooDark
           : shows(shader::PBR_DIELECTRIC_TOO_BRIGHT) ? PbrVerdict::DielectricTooBright
           : shows(shader::PBR_METAL_TOO_DARK)        ? PbrVerdict::MetalTooDark
                                                      : PbrVerdict::Ok;
}

PbrTally tallyPbrChannel(const LdrImage& shown) {
    PbrTally tally;
    for (size_t i = 0; i + 3 < shown.rgba.size(); i += 4) {
        const uint8_t* pixel = &shown.rgba[i];
        if (pixel[0] == 0 && pixel[1] == 0 && pixel[2] == 0) {
            continue;
        }
        ++tally.texels;
        const PbrVerdict verdict = pbrVerdictOfShown(pixel);
        tally.dielectricDark += verdict == PbrVerdict::DielectricTooDark;
        tally.dielectricBright += verdict == PbrVerdict::DielectricTooBright;
        tally.metalDark += verdict == PbrVerdict::MetalTooDark;
    }
    return tally;
}

}  // namespace patina
