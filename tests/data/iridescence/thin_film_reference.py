#!/usr/bin/env python3
"""Reference values for KHR_materials_iridescence (thin-film Fresnel).

Independent plain-Python re-implementation of the math described in
/tmp/irid/FORMULAS.md (Belcour & Barla 2017 approximation as used by the
glTF spec "Iridescence Fresnel" implementation notes and the Khronos glTF
Sample Viewer/Renderer).  No numpy needed; float64 throughout (a GLSL
implementation in float32 should match to ~1e-5).

Usage: python3 reference.py
"""
import math

PI = math.pi

# XYZ -> linear Rec.709/sRGB, written ROW-major here (GLSL source lists the
# same numbers column-major in mat3(...)).
XYZ_TO_REC709 = (
    (3.2404542, -1.5371385, -0.4985314),
    (-0.9692660, 1.8760108, 0.0415560),
    (0.0556434, -0.2040259, 1.0572252),
)

# Gaussian fits of the CIE XYZ matching functions in Fourier space.
VAL = (5.4856e-13, 4.4201e-13, 5.2481e-13)
POS = (1.6810e+06, 1.7953e+06, 2.2084e+06)
VAR = (4.3278e+09, 9.3046e+09, 6.6121e+09)
X2_VAL, X2_POS, X2_VAR = 9.7470e-14, 2.2399e+06, 4.5282e+09  # 2nd lobe of x-bar
NORM = 1.0685e-7


def clamp(x, lo, hi):
    return lo if x < lo else hi if x > hi else x


def smoothstep(e0, e1, x):
    t = clamp((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def f_schlick(f0, cos_t, f90=1.0):
    x = clamp(1.0 - cos_t, 0.0, 1.0)
    return f0 + (f90 - f0) * x ** 5


def ior_to_f0(n_t, n_i):
    return ((n_t - n_i) / (n_t + n_i)) ** 2


def f0_to_ior(f0):
    s = math.sqrt(f0)
    return (1.0 + s) / (1.0 - s)


def eval_sensitivity(opd_nm, shift):
    """opd in nm (scalar), shift = per-channel phase (3-tuple). Returns RGB."""
    phase = 2.0 * PI * opd_nm * 1.0e-9
    xyz = [VAL[i] * math.sqrt(2.0 * PI * VAR[i]) * math.cos(POS[i] * phase + shift[i])
           * math.exp(-phase * phase * VAR[i]) for i in range(3)]
    # extra lobe added to X only, using the X (red) channel's shift
    xyz[0] += (X2_VAL * math.sqrt(2.0 * PI * X2_VAR) * math.cos(X2_POS * phase + shift[0])
               * math.exp(-X2_VAR * phase * phase))
    xyz = [c / NORM for c in xyz]
    return tuple(sum(XYZ_TO_REC709[r][c] * xyz[c] for c in range(3)) for r in range(3))


def eval_iridescence(outside_ior, film_ior, cos_theta1, thickness_nm, base_f0,
                     variant="viewer"):
    """Thin-film Fresnel, RGB.

    variant="viewer": glTF Sample Viewer/Renderer iridescence.glsl
        (smoothstep fade of film ior, baseIor from clamp(F0, 0, 0.9999)).
    variant="spec": ratified spec implementation notes
        (no smoothstep, baseIor from F0 + 0.0001).
    """
    if variant == "viewer":
        n2 = outside_ior + (film_ior - outside_ior) * smoothstep(0.0, 0.03, thickness_nm)
    else:
        n2 = film_ior
    sin2_sq = (outside_ior / n2) ** 2 * (1.0 - cos_theta1 ** 2)
    cos2_sq = 1.0 - sin2_sq
    if cos2_sq < 0.0:           # total internal reflection (only if film_ior < outside_ior)
        return (1.0, 1.0, 1.0)
    cos2 = math.sqrt(cos2_sq)

    # interface 1: outside -> film (scalar)
    R0 = ior_to_f0(n2, outside_ior)
    R12 = f_schlick(R0, cos_theta1)
    T121 = 1.0 - R12
    phi12 = PI if n2 < outside_ior else 0.0
    phi21 = PI - phi12

    # interface 2: film -> base (per channel)
    if variant == "viewer":
        base_ior = [f0_to_ior(clamp(f, 0.0, 0.9999)) for f in base_f0]
    else:
        base_ior = [f0_to_ior(f + 0.0001) for f in base_f0]
    R1 = [ior_to_f0(b, n2) for b in base_ior]
    R23 = [f_schlick(r, cos2) for r in R1]
    phi23 = [PI if b < n2 else 0.0 for b in base_ior]

    opd = 2.0 * n2 * thickness_nm * cos2          # nm
    phi = [phi21 + p for p in phi23]

    R123 = [clamp(R12 * r, 1e-5, 0.9999) for r in R23]
    r123 = [math.sqrt(r) for r in R123]
    Rs = [T121 ** 2 * R23[i] / (1.0 - R123[i]) for i in range(3)]

    I = [R12 + Rs[i] for i in range(3)]           # m = 0 (DC term)
    Cm = [Rs[i] - T121 for i in range(3)]
    for m in (1, 2):
        Sm = eval_sensitivity(m * opd, [m * p for p in phi])
        for i in range(3):
            Cm[i] *= r123[i]
            I[i] += Cm[i] * 2.0 * Sm[i]
    return tuple(max(v, 0.0) for v in I)


def rgb_mix(base, layer, a):
    amax = max(a)
    return tuple((1.0 - amax) * base[i] + a[i] * layer[i] for i in range(3))


def viewer_weights(f_irid_d, f_irid_m, factor, thickness_nm, VdotH, f0_d=0.04, base_color=(1, 1, 1)):
    """Current viewer (glTF-Sample-Renderer pbr.frag) per-light lobe weights.
    Returns (diffuse_weight_rgb, dielectric_spec_weight_rgb, metal_spec_weight_rgb),
    i.e. dielectric_brdf = dw*diffuse + sw*specular, metal_brdf = mw*specular."""
    if thickness_nm == 0.0:
        factor = 0.0
    fd = f_schlick(f0_d, abs(VdotH))
    fm = [f_schlick(c, abs(VdotH)) for c in base_color]
    amax = max(f_irid_d)
    dw = tuple((1 - factor) * (1 - fd) + factor * (1 - amax) for _ in range(3))
    sw = tuple((1 - factor) * fd + factor * f_irid_d[i] for i in range(3))
    mw = tuple((1 - factor) * fm[i] + factor * f_irid_m[i] for i in range(3))
    return dw, sw, mw


def fmt(v):
    return "(" + ", ".join("%.5f" % x for x in v) + ")"


def main():
    F0_D = ((1.5 - 1.0) / (1.5 + 1.0)) ** 2     # 0.04
    F0_M = (0.95, 0.64, 0.54)
    print("evalIridescence (viewer variant), outside ior 1.0; RGB linear Rec.709")
    print("F0 dielectric = %.6f (ior 1.5); metal F0 = %s" % (F0_D, F0_M))
    print("%-5s %-5s %-5s | %-27s | %-27s" % ("film", "d_nm", "cos", "dielectric F0=0.04", "metal F0=(.95,.64,.54)"))
    for film in (1.3, 1.8):
        for d in (0.0, 100.0, 400.0, 800.0):
            for c in (1.0, 0.7, 0.3):
                fd = eval_iridescence(1.0, film, c, d, (F0_D,) * 3)
                fm = eval_iridescence(1.0, film, c, d, F0_M)
                print("%-5.1f %-5g %-5.1f | %s | %s" % (film, d, c, fmt(fd), fmt(fm)))
    print()
    print("Plain Schlick for comparison (what thickness 0 should give):")
    for c in (1.0, 0.7, 0.3):
        print("  cos %.1f: dielectric %.5f   metal %s" % (
            c, f_schlick(F0_D, c), fmt([f_schlick(f, c) for f in F0_M])))
    print()
    print("Spec-notes variant (no smoothstep, F0+0.0001) at thickness 0, film 1.3:")
    for c in (1.0, 0.7, 0.3):
        print("  cos %.1f: dielectric %s   metal %s" % (
            c, fmt(eval_iridescence(1.0, 1.3, c, 0.0, (F0_D,) * 3, "spec")),
            fmt(eval_iridescence(1.0, 1.3, c, 0.0, F0_M, "spec"))))
    print()
    print("Sanity: eval_sensitivity(0, 0) = %s (~white, ~1)" % fmt(eval_sensitivity(0.0, (0, 0, 0))))
    print("TIR example: outside 1.5, film 1.3, cos 0.3, d 400 -> %s" %
          fmt(eval_iridescence(1.5, 1.3, 0.3, 400.0, (F0_D,) * 3)))
    print()
    print("Viewer lobe weights, factor 1.0, film 1.3, d 400 nm, cos(N.V)=0.7, VdotH 0.7:")
    fi_d = eval_iridescence(1.0, 1.3, 0.7, 400.0, (F0_D,) * 3)
    fi_m = eval_iridescence(1.0, 1.3, 0.7, 400.0, F0_M)
    dw, sw, mw = viewer_weights(fi_d, fi_m, 1.0, 400.0, 0.7, F0_D, F0_M)
    print("  diffuse weight %s  dielectric spec weight %s  metal spec weight %s" % (fmt(dw), fmt(sw), fmt(mw)))
    dw, sw, mw = viewer_weights(fi_d, fi_m, 0.5, 400.0, 0.7, F0_D, F0_M)
    print("  factor 0.5 ->  diffuse %s  diel spec %s  metal spec %s" % (fmt(dw), fmt(sw), fmt(mw)))


if __name__ == "__main__":
    main()
