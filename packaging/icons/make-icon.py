#!/usr/bin/env python3
# Run in this folder: python3 make-icon.py (writes the PNG and the SVG).
# Renders the icon's PNG from the same shapes as the SVG: a rounded tile of bevelled bricks lit
# from the top left, with the parallax "layers" offset. Pure Python (zlib) so it needs nothing.
import zlib, struct, math
N = 256
def inside_round_rect(x, y, x0, y0, x1, y1, r):
    cx = min(max(x, x0 + r), x1 - r); cy = min(max(y, y0 + r), y1 - r)
    return (x - cx) ** 2 + (y - cy) ** 2 <= r * r
bricks = []
rows = [(40, 88), (98, 146), (156, 204)]
for i, (y0, y1) in enumerate(rows):
    off = 0 if i % 2 == 0 else -50
    x = 28 + off
    while x < 228:
        bricks.append((max(x, 28), y0, min(x + 92, 228), y1))
        x += 100
def pixel(px, py):
    x, y = px + 0.5, py + 0.5
    if not inside_round_rect(x, y, 8, 8, 248, 248, 40):
        return (0, 0, 0, 0)
    # background tile: dark slate
    col = (38, 50, 72)
    for (x0, y0, x1, y1) in bricks:
        if x0 + 2 <= x <= x1 - 2 and y0 <= y <= y1:
            # bevel: lighter on top/left edges, darker bottom/right
            d = min(x - x0, x1 - x, y - y0, y1 - y)
            base = (214, 120, 72)
            if d < 7:
                if (y - y0) == d or (x - x0) == d or (y - y0) < 7 and (y - y0) <= (x - x0):
                    k = 1.25
                else:
                    k = 0.7
                if y - y0 < 7 and y - y0 <= min(x - x0, x1 - x):
                    k = 1.3
                elif x - x0 < 7 and x - x0 <= min(y - y0, y1 - y):
                    k = 1.15
                elif y1 - y < 7:
                    k = 0.6
                elif x1 - x < 7:
                    k = 0.75
                base = tuple(min(255, int(c * k)) for c in base)
            col = base
    return col + (255,)
raw = bytearray()
for py in range(N):
    raw.append(0)
    for px in range(N):
        raw.extend(pixel(px, py))
def chunk(t, d):
    c = struct.pack('>I', len(d)) + t + d
    return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', N, N, 8, 6, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + chunk(b'IEND', b'')
open('org.parallaxstudio.ParallaxStudio.png', 'wb').write(png)
# The SVG: the same tile and bricks as vectors.
out = ['<svg xmlns="http://www.w3.org/2000/svg" width="256" height="256" viewBox="0 0 256 256">',
       '  <title>Parallax Studio</title>',
       '  <defs>',
       '    <linearGradient id="bevel" x1="0" y1="0" x2="0.35" y2="1">',
       '      <stop offset="0" stop-color="#ff9c5d"/><stop offset="0.15" stop-color="#d67848"/>',
       '      <stop offset="0.85" stop-color="#d67848"/><stop offset="1" stop-color="#80482b"/>',
       '    </linearGradient>',
       '  </defs>',
       '  <rect x="8" y="8" width="240" height="240" rx="40" fill="#263248"/>']
for (x0, y0, x1, y1) in bricks:
    out.append(f'  <rect x="{x0 + 2}" y="{y0}" width="{x1 - x0 - 4}" height="{y1 - y0}" rx="3" fill="url(#bevel)"/>')
out.append('</svg>')
open('org.parallaxstudio.ParallaxStudio.svg', 'w').write('\n'.join(out) + '\n')
