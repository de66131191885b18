"""Converts the PUMA 560 visual meshes of the Robotics Toolbox for Python (rtb-data,
xacro/puma560_description, MIT) into the binary STL files robopro ships, in the robot file's
base coordinates at the zero position, one file per link and colour class.

Usage: python3 docs/tools/puma2stl.py SRC_DIR OUT_DIR
SRC_DIR holds puma560_link1.dae .. puma560_link7.dae. Prints each output's triangle count and
bounding box, and the joint axes of the source chain next to the robot file's.

The source chain (urdf/puma560_robot.urdf.xacro) has the DH zero pose of the robot file, but
its shoulder is 48 mm lower (a shorter pedestal) and its forearm/wrist axes lie about 20 mm
from the Corke & Armstrong-Helouvry values the robot file uses. Each link's mesh is therefore
moved so that the axis it turns about lies on the robot file's axis (shown by the printout);
along that axis it is moved as far as the next joint needs; the pedestal is stretched in height
to the robot file's 672 mm shoulder.
"""
import math, struct, sys, os
import xml.etree.ElementTree as ET

NS = '{http://www.collada.org/2005/11/COLLADASchema}'

def rx(a): c, s = math.cos(a), math.sin(a); return [[1, 0, 0], [0, c, -s], [0, s, c]]
def ry(a): c, s = math.cos(a), math.sin(a); return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
def rz(a): c, s = math.cos(a), math.sin(a); return [[c, -s, 0], [s, c, 0], [0, 0, 1]]
def mat_mul(a, b): return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
def mat_vec(a, v): return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]
def rpy(r, p, y): return mat_mul(rz(y), mat_mul(ry(p), rx(r)))
def add(a, b): return [a[i] + b[i] for i in range(3)]

PI = math.pi
# Lengths of the source xacro (metres).
L1_1, L2_1, L2_2, L3_2, L3_3 = 0.54864, 0.07493, 0.14224, 0.0254, 0.4318
L4_3, L4_4Z, L4_4Y, L5_4, L5_5, L6_5, L6_6, L7_6 = 0.0, 0.35179, -0.0381, 0.02032, 0.059979, 0.0, 0.05334, 0.0
# Joint origins (xyz, rpy) in the parent link frame and the joint axis in the child frame.
JOINTS = [((0, 0, L1_1), (PI / 2, 0, 0), (0, 1, 0)), ((0, L2_1, L2_2), (0, 0, 0), (0, 0, 1)),
          ((L3_3, 0, L3_2), (0, 0, PI / 2), (0, 0, 1)), ((L4_4Z, 0, L4_4Y + L4_3), (-PI / 2, 0, -PI / 2), (0, 0, 1)),
          ((0, 0, L5_4 + L5_5), (PI / 2, 0, 0), (0, 0, 1)), ((0, L6_6 + L6_5, 0), (-PI / 2, 0, 0), (0, 0, 1))]
# Visual origin of each link's mesh in its link frame (links 1..7 = robopro links 0..6).
VISUAL = [(0, 0, 0), (0, L2_1, 0), (0, 0, L3_2), (0, 0, L4_3), (0, 0, L5_4), (0, 0, L6_5), (0, 0, L7_6)]

# The robot file (models/.../puma560.robot.json), metres: joint points and axes at zero.
ROBOT = [((0, 0, 0), (0, 0, 1)), ((0, 0, 0.672), (0, -1, 0)), ((0.4318, 0, 0.672), (0, -1, 0)),
         ((0.4521, -0.15005, 0.672), (0, 0, 1)), ((0.4521, -0.15005, 1.1038), (0, -1, 0)),
         ((0.4521, -0.15005, 1.1038), (0, 0, 1))]


def source_frames():
    R = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    p = [0, 0, 0]
    frames, axes = [(R, p)], []
    for xyz, r, ax in JOINTS:
        p = add(p, mat_vec(R, xyz))
        R = mat_mul(R, rpy(*r))
        frames.append((R, p))
        axes.append((p, mat_vec(R, ax)))
    return frames, axes


def link_shifts(axes):
    """Per robopro link 1..6 the translation that puts the source's joint axis on the robot file's."""
    d = [[ROBOT[j][0][i] - axes[j][0][i] for i in range(3)] for j in range(6)]
    # Axis 1 (z): its xy already agree; along z take the shoulder height (joint 2).
    s1 = [0, 0, d[1][2]]
    # Axes 2, 3 (along y): x, z from their own axis; y from the forearm's roll axis (joint 4).
    s2 = [d[1][0], d[3][1], d[1][2]]
    s3 = [d[2][0], d[3][1], d[2][2]]
    # Axis 4 (z): x, y from itself; z from the wrist centre (joint 5).
    s4 = [d[3][0], d[3][1], d[4][2]]
    # Axis 5 (along y): x, z from itself; y from joint 6.
    s5 = [d[4][0], d[5][1], d[4][2]]
    # Axis 6 (z): x, y from itself; z as the wrist centre.
    s6 = [d[5][0], d[5][1], d[4][2]]
    return [None, s1, s2, s3, s4, s5, s6]


def read_dae(path):
    """Triangles per material, with the material's diffuse colour."""
    root = ET.parse(path).getroot()
    colour = {}
    effects = {e.get('id'): e for e in root.iter(f'{NS}effect')}
    for m in root.iter(f'{NS}material'):
        eff = effects[m.find(f'{NS}instance_effect').get('url')[1:]]
        c = eff.find(f'.//{NS}diffuse/{NS}color')
        colour[m.get('id')] = [float(x) for x in c.text.split()][:3] if c is not None else [0.6, 0.6, 0.6]
    out = {}
    for g in root.iter(f'{NS}geometry'):
        mesh = g.find(f'{NS}mesh')
        srcs = {'#' + s.get('id'): [float(x) for x in s.find(f'{NS}float_array').text.split()] for s in mesh.findall(f'{NS}source')}
        verts = {'#' + v.get('id'): srcs[v.find(f'{NS}input[@semantic="POSITION"]').get('source')] for v in mesh.findall(f'{NS}vertices')}
        for prim in mesh.findall(f'{NS}triangles'):
            inputs = prim.findall(f'{NS}input')
            stride = max(int(i.get('offset')) for i in inputs) + 1
            vin = [i for i in inputs if i.get('semantic') == 'VERTEX'][0]
            pos = verts[vin.get('source')]
            off = int(vin.get('offset'))
            p = [int(x) for x in prim.find(f'{NS}p').text.split()]
            idx = [p[i + off] for i in range(0, len(p), stride)]
            tris = [[pos[3 * k:3 * k + 3] for k in idx[i:i + 3]] for i in range(0, len(idx), 3)]
            out.setdefault(tuple(colour.get(prim.get('material'), [0.6, 0.6, 0.6])), []).extend(tris)
    return out


def colour_class(rgb):
    r, g, b = rgb
    if r > 0.5 and g < 0.2 and b < 0.2:
        return 'red'
    return 'body' if (r + g + b) / 3 > 0.45 else 'dark'


def write_stl(path, tris):
    lo, hi = [1e9] * 3, [-1e9] * 3
    with open(path, 'wb') as f:
        f.write(b'robopro: from rtb-data puma560_description (MIT)'.ljust(80, b' '))
        f.write(struct.pack('<I', len(tris)))
        for t in tris:
            f.write(struct.pack('<3f', 0, 0, 0))
            for v in t:
                for i in range(3): lo[i] = min(lo[i], v[i]); hi[i] = max(hi[i], v[i])
                f.write(struct.pack('<3f', *v))
            f.write(b'\0\0')
    print(os.path.basename(path), len(tris), 'triangles, bbox', [round(x, 3) for x in lo], [round(x, 3) for x in hi])


def main(src, dst):
    frames, axes = source_frames()
    for j, ((p, a), (rp, ra)) in enumerate(zip(axes, ROBOT)):
        print(f'joint {j + 1}: source point {[round(x, 4) for x in p]} axis {[round(x, 3) for x in a]}; '
              f'robot file {list(rp)} axis {list(ra)}')
    shifts = link_shifts(axes)
    pedestal_stretch = ROBOT[1][0][2] / (L1_1 + L2_1)
    os.makedirs(dst, exist_ok=True)
    for link in range(7):
        R, p = frames[link]
        groups = {}
        for rgb, tris in read_dae(os.path.join(src, f'puma560_link{link + 1}.dae')).items():
            groups.setdefault(colour_class(rgb), []).extend(tris)
        for cls, tris in sorted(groups.items()):
            moved = []
            for t in tris:
                tt = []
                for v in t:
                    w = add(mat_vec(R, add(v, VISUAL[link])), p)
                    if link == 0:
                        w[2] *= pedestal_stretch
                    else:
                        w = add(w, shifts[link])
                    tt.append(w)
                moved.append(tt)
            name = f'link_{link}' + ('' if cls == 'body' else '-' + cls) + '.stl'
            write_stl(os.path.join(dst, name), moved)
    print('shifts', [None if s is None else [round(x, 4) for x in s] for s in shifts], 'pedestal stretch', round(pedestal_stretch, 4))


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])
