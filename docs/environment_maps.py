#!/usr/bin/env python3
"""Two lat-long HDR maps of the kinds users light heads with, for measuring
the environment light against the CPU reference (docs/environment.md, "The
dominant light"):

  outdoor.hdr  a clear sky with a low sun (10 degrees up, 1.2 degrees wide,
               radiance 2e4), a glow around it, broken clouds and a textured
               ground;
  indoor.hdr   a dim studio (walls 0.04) with a rectangular key soft box
               (14 x 20 degrees, radiance 40), a larger fill box, a ceiling
               strip and a window behind.

    python3 docs/environment_maps.py [--out-dir DIR] [--height 256]

Radiance RGBE files (uncompressed scanlines), width twice the height, in the
layout of engine/env/SphericalHarmonics.h: +Y up, row 0 at the top, column u
at longitude 2 pi (u + 0.5) / W from +Z towards +X. Deterministic (a hashed
value noise, no random state). Pure Python: a few seconds at 512 x 256.
"""
import argparse
import math
import os


def normalise(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def direction(u, v, width, height):
    phi = 2.0 * math.pi * (u + 0.5) / width
    theta = math.pi * (v + 0.5) / height
    return (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))


def towards(azimuth_deg, elevation_deg):
    a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
    return (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))


def hash01(i, j, salt):
    h = (i * 374761393 + j * 668265263 + salt * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFFFF) / float(0xFFFFFF)


def value_noise(x, y, salt):
    """Smooth value noise on a lattice, period-free, in [0, 1]."""
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a, b = hash01(i, j, salt), hash01(i + 1, j, salt)
    c, d = hash01(i, j + 1, salt), hash01(i + 1, j + 1, salt)
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy


def fbm(x, y, salt, octaves=4):
    total, amplitude, norm = 0.0, 1.0, 0.0
    for o in range(octaves):
        total += amplitude * value_noise(x * 2 ** o, y * 2 ** o, salt + o)
        norm += amplitude
        amplitude *= 0.5
    return total / norm


def smoothstep(e0, e1, x):
    t = min(max((x - e0) / (e1 - e0), 0.0), 1.0)
    return t * t * (3 - 2 * t)


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def outdoor(width, height):
    sun = towards(45.0, 10.0)
    sun_radius = math.radians(0.6)
    sun_radiance = (2.0e4, 1.8e4, 1.5e4)
    pixels = [[(0.0, 0.0, 0.0)] * width for _ in range(height)]
    sun_texels, sun_solid_angle = [], 0.0
    nearest, nearest_dot, nearest_solid_angle = None, -2.0, 0.0  # for a sun smaller than a texel
    for v in range(height):
        row_solid_angle = 2 * math.pi / width * (math.cos(math.pi * v / height) - math.cos(math.pi * (v + 1) / height))
        for u in range(width):
            d = direction(u, v, width, height)
            if d[1] >= 0.0:
                t = (1.0 - d[1]) ** 3
                sky = mix((0.18, 0.32, 0.75), (0.85, 0.9, 1.0), t)
                glow = 8.0 * math.exp(-math.acos(max(min(dot(d, sun), 1.0), -1.0)) / math.radians(6.0))
                sky = tuple(s + glow * c for s, c in zip(sky, (1.0, 0.85, 0.6)))
                # Broken clouds between 3 and 45 degrees up, lit towards the sun.
                phi = math.atan2(d[0], d[2])
                elevation = math.asin(d[1])
                cover = smoothstep(0.55, 0.75, fbm(phi * 3.0, elevation * 6.0, 11)) * smoothstep(0.05, 0.15, elevation) \
                    * (1.0 - smoothstep(0.5, 0.8, elevation))
                cloud = 1.4 + 1.2 * max(dot(d, sun), 0.0)
                radiance = mix(sky, (cloud, cloud * 0.97, cloud * 0.93), cover)
            else:
                g = 0.6 + 0.8 * fbm(d[0] / max(-d[1], 0.05) * 2.0, d[2] / max(-d[1], 0.05) * 2.0, 23)
                radiance = (0.09 * g, 0.1 * g, 0.05 * g)
            pixels[v][u] = radiance
            if math.acos(max(min(dot(d, sun), 1.0), -1.0)) <= sun_radius:
                sun_texels.append((u, v))
                sun_solid_angle += row_solid_angle
            if dot(d, sun) > nearest_dot:
                nearest, nearest_dot, nearest_solid_angle = (u, v), dot(d, sun), row_solid_angle
    if not sun_texels:
        # No texel centre within the disc (--height 128 and below): its whole power goes to the nearest
        # texel, so the sun is not lost (it was, and the glow around it became the dominant light).
        sun_texels, sun_solid_angle = [nearest], nearest_solid_angle
    # The sun's power, radiance x its disc's solid angle, spread over the texels it covers.
    disc = 2 * math.pi * (1 - math.cos(sun_radius))
    for u, v in sun_texels:
        pixels[v][u] = tuple(c * disc / sun_solid_angle for c in sun_radiance)
    return pixels


def box_coverage(d, box):
    """1 inside a rectangular soft box (angular half-sizes), a 1-degree soft edge, 0 outside."""
    forward, half_width, half_height, _ = box
    along = dot(d, forward)
    if along <= 0.0:
        return 0.0
    right = normalise(cross((0.0, 1.0, 0.0), forward))
    up = cross(forward, right)
    a = math.degrees(math.atan2(dot(d, right), along))
    b = math.degrees(math.atan2(dot(d, up), along))
    return smoothstep(half_width + 0.5, half_width - 0.5, abs(a)) * smoothstep(half_height + 0.5, half_height - 0.5, abs(b))


def indoor(width, height):
    boxes = [
        (towards(40.0, 25.0), 7.0, 10.0, (40.0, 39.0, 37.0)),      # key: 14 x 20 degrees
        (towards(-60.0, 10.0), 12.0, 14.0, (6.0, 6.2, 6.6)),       # fill
        (towards(0.0, 80.0), 1.5, 20.0, (15.0, 15.0, 14.0)),       # ceiling strip
        (towards(180.0, 15.0), 15.0, 10.0, (1.6, 1.9, 2.4)),       # window behind
    ]
    pixels = [[(0.0, 0.0, 0.0)] * width for _ in range(height)]
    for v in range(height):
        for u in range(width):
            d = direction(u, v, width, height)
            if d[1] >= 0.0:
                w = 0.035 + 0.015 * d[1] + 0.01 * fbm(u / 24.0, v / 24.0, 5)
                radiance = (w, w * 0.98, w * 0.95)
            else:
                g = 0.02 + 0.01 * fbm(u / 6.0, v / 40.0, 7)
                radiance = (g * 1.1, g * 0.85, g * 0.6)
            for box in boxes:
                c = box_coverage(d, box)
                if c > 0.0:
                    radiance = mix(radiance, box[3], c)
            pixels[v][u] = radiance
    return pixels


def rgbe(colour):
    m = max(colour)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes((int(colour[0] * scale), int(colour[1] * scale), int(colour[2] * scale), exponent + 128))


def write_hdr(path, pixels):
    height, width = len(pixels), len(pixels[0])
    with open(path + ".tmp", "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {height} +X {width}\n".encode())
        for row in pixels:
            f.write(b"".join(rgbe(p) for p in row))
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out-dir", default=".")
    parser.add_argument("--height", type=int, default=256)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    for name, make in (("outdoor", outdoor), ("indoor", indoor)):
        path = os.path.join(args.out_dir, name + ".hdr")
        write_hdr(path, make(2 * args.height, args.height))
        print(path)


if __name__ == "__main__":
    main()
