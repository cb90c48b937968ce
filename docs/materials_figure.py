#!/usr/bin/env python3
"""Side-by-side figures of docs/materials.md, with the standard library only
(zlib PNG reading and writing, 8-bit RGB/RGBA as `dermis render` writes).

    python3 docs/materials_figure.py OUT.png A.png B.png [C.png ...] [--diff SCALE]

Joins the images left to right (same size). With --diff SCALE it appends
|B - A| x SCALE of the first two (largest channel, grey), and prints the
number of pixels that differ and the largest difference (in 8-bit steps).
The commands that made each figure are in docs/materials.md.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), f"{path}: 8-bit RGB or RGBA only"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return rows


def write_png(path, rows):
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(c for pixel in row for c in pixel) for row in rows)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main(args):
    scale = None
    if "--diff" in args:
        at = args.index("--diff")
        scale = float(args[at + 1])
        args = args[:at] + args[at + 2:]
    out, images = args[0], [read_png(p) for p in args[1:]]
    if scale is not None:
        a, b = images[0], images[1]
        diff, changed, largest = [], 0, 0
        for row_a, row_b in zip(a, b):
            row = []
            for pa, pb in zip(row_a, row_b):
                d = max(abs(x - y) for x, y in zip(pa, pb))
                changed += d > 0
                largest = max(largest, d)
                v = min(255, int(d * scale))
                row.append((v, v, v))
            diff.append(row)
        print(f"{changed} pixels differ, largest difference {largest}/255")
        images.append(diff)
    write_png(out, [sum((image[y] for image in images), []) for y in range(len(images[0]))])


if __name__ == "__main__":
    main(sys.argv[1:])
