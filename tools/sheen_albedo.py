#!/usr/bin/env python3
"""Prints the table kSheenAlbedo of glsl/common/bsdf.glsl: the directional albedo of the white sheen lobe.

E(mu_o, r) = integral over the hemisphere of D(h) V(wo, wi) cos(theta_i) dwi for the Charlie distribution
of Estevez & Kulla 2017 ("Production Friendly Microfacet Sheen BRDF"), D(h) = (2 + 1/a) sin(theta_h)^(1/a)
/ (2 pi), a = r^2, and the visibility term of Neubelt & Pettineo 2013, V = 1 / (4 (cos_i + cos_o -
cos_i cos_o)), the pair glTF's KHR_materials_sheen describes. Rows: sheen roughness r = 0.1 + 0.9 j / 15
(bsdf.glsl clamps r to [0.1, 1]); columns: mu_o = i / 15 (the first at 0.001). The midpoint rule in
(theta_i, phi_i), in plain Python (no NumPy on the build machine).
"""
import math

N_THETA, N_PHI, SIZE = 256, 128, 16


def albedo(mu, r):
    a = r * r
    so = math.sqrt(max(0.0, 1.0 - mu * mu))
    dt, dp = (math.pi / 2) / N_THETA, (2 * math.pi) / N_PHI
    norm = (2.0 + 1.0 / a) / (2.0 * math.pi)
    cosines = [math.cos((k + 0.5) * dp) for k in range(N_PHI)]
    total = 0.0
    for i in range(N_THETA):
        t = (i + 0.5) * dt
        st, ct = math.sin(t), math.cos(t)
        weight = norm * ct * st / (4.0 * (ct + mu - ct * mu))
        hz2 = (ct + mu) ** 2
        for c in cosines:
            # |h|^2 with h = wi + wo; sin^2(theta_h) = (hx^2 + hy^2) / |h|^2.
            horizontal = st * st + 2.0 * st * so * c + so * so
            total += weight * (horizontal / (horizontal + hz2)) ** (0.5 / a)
    return total * dt * dp


if __name__ == "__main__":
    rows = [[albedo(max(i / (SIZE - 1), 1e-3), 0.1 + 0.9 * j / (SIZE - 1)) for i in range(SIZE)]
            for j in range(SIZE)]
    print("    " + ",\n    ".join(", ".join("%.4f" % v for v in row) for row in rows))
