"""The PNGs the lessons write and the test scripts read, in plain Python (zlib): 8-bit grey, RGB or
RGBA, not interlaced, each picture as (width, height, channels, pixels), pixels the rows top
first, one byte a channel. Used by tests/lessons/halo_crops.py, dissolve_figures.py and
tests/web/web_check.py."""
import pathlib
import struct
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"
CHANNELS = {0: 1, 2: 3, 6: 4}  # PNG colour type: grey, RGB, RGBA
COLOUR_TYPE = {channels: kind for kind, channels in CHANNELS.items()}


def decode_png(data, name="PNG"):
    """(width, height, channels, pixels) of a PNG's bytes; ValueError naming `name` for another kind."""
    if data[:8] != SIGNATURE:
        raise ValueError(f"{name}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if header is None:
        raise ValueError(f"{name}: no IHDR")
    w, h, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in CHANNELS or interlace:
        raise ValueError(f"{name}: unsupported PNG (8-bit grey, RGB or RGBA, not interlaced)")
    bpp = CHANNELS[colour]
    raw, stride = zlib.decompress(idat), w * bpp
    out, prev = bytearray(), bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        prev = line
    return w, h, bpp, bytes(out)


def read_png(path):
    """(width, height, channels, pixels) of the PNG file at `path`."""
    return decode_png(pathlib.Path(path).read_bytes(), str(path))


def write_png(path, width, height, channels, pixels):
    """Writes pixels (rows top first, `channels` bytes a pixel: 1, 3 or 4) as a PNG file."""
    stride = width * channels
    raw = b"".join(b"\0" + bytes(pixels[y * stride:(y + 1) * stride]) for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, COLOUR_TYPE[channels], 0, 0, 0)
    pathlib.Path(path).write_bytes(SIGNATURE + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
                                   + chunk(b"IEND", b""))
