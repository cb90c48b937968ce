#!/usr/bin/env python3
"""Writes a lat-long HDR environment map with a small, very bright sun over a
dim sky: the hard case for the CPU reference (docs/results/reference.md,
"Speed"). Radiance RGBE (.hdr), uncompressed scanlines, no dependencies.

usage: tools/make_sun_map.py OUT.hdr [--width 1024] [--sun-radiance 1e4]
       [--sun-radius-deg 0.5] [--sun-direction X,Y,Z]

The layout is the engine's (env/SphericalHarmonics.h): column u at longitude
phi = 2 pi (u + 0.5) / W about +Y, row v at colatitude theta = pi (v + 0.5) / H
from +Y, d = (sin theta sin phi, cos theta, sin theta cos phi). The default sun
sits where default.json's key light comes from."""
import argparse
import math
import struct


def rgbe(r, g, b):
    v = max(r, g, b)
    if v < 1e-32:
        return bytes((0, 0, 0, 0))
    mantissa, exponent = math.frexp(v)
    scale = mantissa * 256.0 / v
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("--width", type=int, default=1024)
    parser.add_argument("--sun-radiance", type=float, default=1e4)
    parser.add_argument("--sun-radius-deg", type=float, default=0.5)
    parser.add_argument("--sun-direction", default="0.6,0.35,0.72")
    args = parser.parse_args()
    width, height = args.width, args.width // 2
    sun = [float(c) for c in args.sun_direction.split(",")]
    length = math.sqrt(sum(c * c for c in sun))
    sun = [c / length for c in sun]
    cos_radius = math.cos(math.radians(args.sun_radius_deg))
    rows = []
    for v in range(height):
        theta = math.pi * (v + 0.5) / height
        row = bytearray()
        for u in range(width):
            phi = 2.0 * math.pi * (u + 0.5) / width
            d = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            if d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2] >= cos_radius:
                colour = (args.sun_radiance, 0.92 * args.sun_radiance, 0.8 * args.sun_radiance)
            else:
                up = max(d[1], 0.0)  # a dim blue sky above a darker ground
                colour = (0.05 + 0.1 * up, 0.07 + 0.15 * up, 0.1 + 0.25 * up) if d[1] > 0 else (0.03, 0.025, 0.02)
            row += rgbe(*colour)
        rows.append(bytes(row))
    with open(args.out, "wb") as out:
        out.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        out.write(f"-Y {height} +X {width}\n".encode())
        for row in rows:
            out.write(row)


if __name__ == "__main__":
    main()
