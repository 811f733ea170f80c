#!/usr/bin/env bash
# Makes the PCD test files of this folder with the Point Cloud Library's own PCD writer (not run by CI).
# Needs python3 and PCL's tools (Debian 12: apt-get install pcl-tools, PCL 1.13). Run from anywhere.
#  1. python3 writes two ascii PCD sources from the RELLIS-3D excerpts of tests/data (every float printed with 9
#     significant digits, which a float parses back to the same bits; the double field holds multiples of 1/64):
#     - organized.src.pcd: columns 1000-1063 of rellis3d-os1-4x2048.bin as an organised cloud, WIDTH 64 (columns)
#       x HEIGHT 4 (beams, top to bottom), fields x y z intensity (F 4); point (row b, column c) is record
#       (1000 + c) * 4 + b of the excerpt, and an all-zero record (no return) is written as nan nan nan, as PCL
#       writes missing points of organised clouds;
#     - unorganized.src.pcd: the first 300 returns (non-zero records) of columns 600-679 of
#       rellis3d-os1-16x2048.bin, column by column, beam by beam, WIDTH 300 x HEIGHT 1, fields x y z intensity
#       (F 4), t (F 8: 10 + column / 64) and ring (U 2: the original beam, 4 x the excerpt's beam).
#  2. pcl_convert_pcd_ascii_binary (PCL's PCDReader and PCDWriter) reads each source and writes it as ascii (format 0,
#     precision 9), binary (1) and binary_compressed (2): <name>.ascii.pcd, <name>.binary.pcd, <name>.compressed.pcd.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
data=$here/..
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 - "$data" "$tmp" <<'PY'
import struct, sys
data, out = sys.argv[1], sys.argv[2]

def g(v):   # 9 significant digits: parses back to the same float32
    return 'nan' if v != v else '%.9g' % v

def header(fields, sizes, types, width, height):
    n = len(fields)
    return ('# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS %s\nSIZE %s\nTYPE %s\nCOUNT %s\n'
            'WIDTH %d\nHEIGHT %d\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n'
            % (' '.join(fields), ' '.join(map(str, sizes)), ' '.join(types), ' '.join(['1'] * n),
               width, height, width * height))

d = open(data + '/rellis3d-os1-4x2048.bin', 'rb').read()
lines = []
for b in range(4):
    for c in range(1000, 1064):
        x, y, z, i = struct.unpack_from('<4f', d, ((c * 4) + b) * 16)
        if x == 0 and y == 0 and z == 0:
            x = y = z = float('nan')
        lines.append(' '.join(g(v) for v in (x, y, z, i)))
open(out + '/organized.src.pcd', 'w').write(
    header(['x', 'y', 'z', 'intensity'], [4] * 4, ['F'] * 4, 64, 4) + '\n'.join(lines) + '\n')

d = open(data + '/rellis3d-os1-16x2048.bin', 'rb').read()
lines = []
for c in range(600, 680):
    for b in range(16):
        x, y, z, i = struct.unpack_from('<4f', d, ((c * 16) + b) * 16)
        if (x, y, z) != (0, 0, 0) and len(lines) < 300:
            lines.append('%s %s %s %s %r %d' % (g(x), g(y), g(z), g(i), 10 + c / 64, 4 * b))
assert len(lines) == 300
open(out + '/unorganized.src.pcd', 'w').write(
    header(['x', 'y', 'z', 'intensity', 't', 'ring'], [4, 4, 4, 4, 8, 2], ['F', 'F', 'F', 'F', 'F', 'U'], 300, 1)
    + '\n'.join(lines) + '\n')
PY

for name in organized unorganized; do
  pcl_convert_pcd_ascii_binary "$tmp/$name.src.pcd" "$here/$name.ascii.pcd" 0 9
  pcl_convert_pcd_ascii_binary "$tmp/$name.src.pcd" "$here/$name.binary.pcd" 1
  pcl_convert_pcd_ascii_binary "$tmp/$name.src.pcd" "$here/$name.compressed.pcd" 2
done
(cd "$here" && sha256sum ./*.pcd)
