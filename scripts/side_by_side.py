#!/usr/bin/env python3
"""Puts PNG images side by side, each with a caption underneath, into one PNG.

    python3 scripts/side_by_side.py OUT.png A.png "caption of A" B.png "caption of B" [...]

Standard library only (zlib and struct): it reads 8-bit RGB, RGBA, grey and grey-alpha PNGs
without interlacing (what Blender and Patina write) and writes 8-bit RGB. Captions are drawn in
a small built-in 5x7 pixel font at twice its size; lower case is shown as upper case, and a
character the font lacks as a blank. scripts/compare_blender.sh uses it for docs/performance.
"""
import struct
import sys
import zlib

# 5x7 glyphs drawn for this script, seven rows of five columns ('#' is ink); short rows are
# padded with blanks.
FONT = {
    'A': [' ### ', '#   #', '#   #', '#####', '#   #', '#   #', '#   #'],
    'B': ['#### ', '#   #', '#   #', '#### ', '#   #', '#   #', '#### '],
    'C': [' ### ', '#   #', '#    ', '#    ', '#    ', '#   #', ' ### '],
    'D': ['#### ', '#   #', '#   #', '#   #', '#   #', '#   #', '#### '],
    'E': ['#####', '#    ', '#    ', '#### ', '#    ', '#    ', '#####'],
    'F': ['#####', '#    ', '#    ', '#### ', '#    ', '#    ', '#    '],
    'G': [' ### ', '#   #', '#    ', '# ###', '#   #', '#   #', ' ####'],
    'H': ['#   #', '#   #', '#   #', '#####', '#   #', '#   #', '#   #'],
    'I': [' ### ', '  #  ', '  #  ', '  #  ', '  #  ', '  #  ', ' ### '],
    'J': ['  ###', '   # ', '   # ', '   # ', '   # ', '#  # ', ' ##  '],
    'K': ['#   #', '#  # ', '# #  ', '##   ', '# #  ', '#  # ', '#   #'],
    'L': ['#    ', '#    ', '#    ', '#    ', '#    ', '#    ', '#####'],
    'M': ['#   #', '## ##', '# # #', '# # #', '#   #', '#   #', '#   #'],
    'N': ['#   #', '##  #', '# # #', '#  ##', '#   #', '#   #', '#   #'],
    'O': [' ### ', '#   #', '#   #', '#   #', '#   #', '#   #', ' ### '],
    'P': ['#### ', '#   #', '#   #', '#### ', '#    ', '#    ', '#    '],
    'Q': [' ### ', '#   #', '#   #', '#   #', '# # #', '#  # ', ' ## #'],
    'R': ['#### ', '#   #', '#   #', '#### ', '# #  ', '#  # ', '#   #'],
    'S': [' ####', '#    ', '#    ', ' ### ', '    #', '    #', '#### '],
    'T': ['#####', '  #  ', '  #  ', '  #  ', '  #  ', '  #  ', '  #  '],
    'U': ['#   #', '#   #', '#   #', '#   #', '#   #', '#   #', ' ### '],
    'V': ['#   #', '#   #', '#   #', '#   #', '#   #', ' # # ', '  #  '],
    'W': ['#   #', '#   #', '#   #', '# # #', '# # #', '# # #', ' # # '],
    'X': ['#   #', '#   #', ' # # ', '  #  ', ' # # ', '#   #', '#   #'],
    'Y': ['#   #', '#   #', ' # # ', '  #  ', '  #  ', '  #  ', '  #  '],
    'Z': ['#####', '    #', '   # ', '  #  ', ' #   ', '#    ', '#####'],
    '0': [' ### ', '#   #', '#  ##', '# # #', '##  #', '#   #', ' ### '],
    '1': ['  #  ', ' ##  ', '  #  ', '  #  ', '  #  ', '  #  ', ' ### '],
    '2': [' ### ', '#   #', '    #', '   # ', '  #  ', ' #   ', '#####'],
    '3': ['#####', '   # ', '  #  ', '   # ', '    #', '#   #', ' ### '],
    '4': ['   # ', '  ## ', ' # # ', '#  # ', '#####', '   # ', '   # '],
    '5': ['#####', '#    ', '#### ', '    #', '    #', '#   #', ' ### '],
    '6': ['  ## ', ' #   ', '#    ', '#### ', '#   #', '#   #', ' ### '],
    '7': ['#####', '    #', '   # ', '  #  ', ' #   ', ' #   ', ' #   '],
    '8': [' ### ', '#   #', '#   #', ' ### ', '#   #', '#   #', ' ### '],
    '9': [' ### ', '#   #', '#   #', ' ####', '    #', '   # ', ' ##  '],
    ' ': ['', '', '', '', '', '', ''],
    '.': ['', '', '', '', '', ' ## ', ' ## '],
    ',': ['', '', '', '', ' ## ', ' ## ', '  # '],
    ':': ['', ' ## ', ' ## ', '', '', ' ## ', ' ## '],
    '-': ['', '', '', '#####', '', '', ''],
    '(': ['   # ', '  #  ', ' #   ', ' #   ', ' #   ', '  #  ', '   # '],
    ')': [' #   ', '  #  ', '   # ', '   # ', '   # ', '  #  ', ' #   '],
    '/': ['    #', '    #', '   # ', '  #  ', ' #   ', '#    ', '#    '],
    '=': ['', '', '#####', '', '#####', '', ''],
    '+': ['', '  #  ', '  #  ', '#####', '  #  ', '  #  ', ''],
    '%': ['##   ', '##  #', '   # ', '  #  ', ' #   ', '#  ##', '   ##'],
    "'": ['  #  ', '  #  ', ' #   ', '', '', '', ''],
}
FONT = {key: "".join(row.ljust(5) for row in rows) for key, rows in FONT.items()}
SCALE = 2
CAPTION_HEIGHT = (7 + 6) * SCALE


def read_png(path):
    with open(path, "rb") as file:
        data = file.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    position, header, compressed = 8, None, b""
    while position < len(data):
        (length,) = struct.unpack(">I", data[position:position + 4])
        kind = data[position + 4:position + 8]
        body = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed += body
        elif kind == b"IEND":
            break
    if header is None:
        raise ValueError(f"{path}: no IHDR chunk")
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise ValueError(f"{path}: only 8-bit, non-interlaced grey/RGB/RGBA PNGs are read "
                         f"(depth {depth}, colour type {colour}, interlace {interlace})")
    raw = zlib.decompress(compressed)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
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
                estimate = left + up - corner
                a, b, c = abs(estimate - left), abs(estimate - up), abs(estimate - corner)
                line[i] = (line[i] + (left if a <= b and a <= c else up if b <= c else corner)) & 255
            elif kind != 0:
                raise ValueError(f"{path}: unknown filter {kind} on row {y}")
        rows.append(bytes(to_rgb(line, channels)))
        previous = line
    return width, height, rows


def to_rgb(line, channels):
    if channels == 3:
        return line
    out = bytearray()
    for i in range(0, len(line), channels):
        if channels in (1, 2):
            out += bytes((line[i],)) * 3
        else:
            out += line[i:i + 3]
    return out


def write_png(path, width, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    header = struct.pack(">IIBBBBB", width, len(rows), 8, 2, 0, 0, 0)
    with open(path, "wb") as file:
        file.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
                   + chunk(b"IEND", b""))


def draw_text(rows, x0, y0, text, width):
    x = x0
    for character in text.upper():
        glyph = FONT.get(character, FONT[" "])
        for gy in range(7):
            for gx in range(5):
                if glyph[gy * 5 + gx] != "#":
                    continue
                for dy in range(SCALE):
                    for dx in range(SCALE):
                        px = x + gx * SCALE + dx
                        if 0 <= px < width:
                            rows[y0 + gy * SCALE + dy][px * 3:px * 3 + 3] = b"\xf0\xf0\xf0"
        x += 6 * SCALE


def main(argv):
    if len(argv) < 4 or len(argv) % 2 != 0:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    out, pairs = argv[1], list(zip(argv[2::2], argv[3::2]))
    images = [read_png(path) for path, _ in pairs]
    gap = 8
    height = max(h for _, h, _ in images)
    width = sum(w for w, _, _ in images) + gap * (len(images) + 1)
    background = b"\x20\x20\x22"
    rows = [bytearray(background * width) for _ in range(gap + height + CAPTION_HEIGHT + gap)]
    x = gap
    for (w, h, image_rows), (_, caption) in zip(images, pairs):
        for y in range(h):
            rows[gap + y][x * 3:(x + w) * 3] = image_rows[y]
        text_width = len(caption) * 6 * SCALE
        draw_text(rows, x + max(0, (w - text_width) // 2), gap + height + 4 * SCALE, caption, x + w)
        x += w + gap
    write_png(out, width, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
