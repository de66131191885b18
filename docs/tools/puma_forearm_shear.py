"""Closes the step between the PUMA 560 forearm casting and its wrist in robopro's shipped meshes.

Usage: python3 docs/tools/puma_forearm_shear.py LINK_3_STL

The source model (rtb-data puma560_description) has its wrist on the elbow's line (a3 = 0);
the robot file uses Corke & Armstrong-Helouvry's a3 = 20.3 mm, so puma2stl.py puts links 4-6 on
the robot file's wrist axis, 20.3 mm along base x (at the zero position) from where the source
forearm ends. Moving the whole forearm would take its elbow housing off axis 3; instead the
column between the elbow housing (z = 0.74 m) and the wrist collar (z = 1.00 m) is sheared
along x, from 0 at the housing to the full 20.3 mm at the collar, and the collar moves with the
wrist. A real PUMA's forearm is likewise offset from its elbow by a3. The file (binary STL, base
coordinates at the zero position) is rewritten whole.
"""
import os, struct, sys

A3 = 0.0203                # m, robot file a3 (joint 4 point x 0.4521 - joint 3 point x 0.4318)
Z_HOUSING, Z_COLLAR = 0.74, 1.00


def shear(x, z):
    t = min(1.0, max(0.0, (z - Z_HOUSING) / (Z_COLLAR - Z_HOUSING)))
    return x + A3 * t


def main(path):
    b = bytearray(open(path, 'rb').read())
    n = struct.unpack_from('<I', b, 80)[0]
    if len(b) != 84 + 50 * n:
        sys.exit(f'{path}: not a binary STL')
    for t in range(n):
        for k in range(3):
            o = 84 + 50 * t + 12 + 12 * k
            x, y, z = struct.unpack_from('<3f', b, o)
            struct.pack_into('<3f', b, o, shear(x, z), y, z)
    tmp = path + '.tmp'
    with open(tmp, 'wb') as f:
        f.write(b)
    os.replace(tmp, path)
    print(path, n, 'triangles sheared')


if __name__ == '__main__':
    main(sys.argv[1])
