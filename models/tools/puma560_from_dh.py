#!/usr/bin/env python3
"""Joint axes, flange and centres of mass of the PUMA 560 at its zero position, from its
standard Denavit-Hartenberg table (robots.md; Corke & Armstrong-Helouvry 1994, as used by the
Robotics Toolbox). Produces the numbers of
models/src/main/resources/org/robopro/models/robots/puma560.robot.json.

Conventions (standard DH): A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i), base = the table's
frame 0, flange = frame 6, all joint values zero (the table has no offsets, so the controller zero
is the DH zero). Joint i turns about z_{i-1} through the origin of frame i-1.
Centres of mass r_i are given in link frame i (Robotics Toolbox mdl_puma560.m, "params of 8/95").
Run: python3 models/tools/puma560_from_dh.py   (no dependencies; lengths printed in mm)
"""
import math

# d (m), a (m), alpha (deg)
DH = [(0.672, 0, 90), (0, 0.4318, 0), (0.15005, 0.0203, -90), (0.4318, 0, 90), (0, 0, -90), (0, 0, 0)]
# link mass (kg) and centre of mass in link frame i (m); link 1 has no listed mass (turns about vertical).
MASS = [(0.0, (0, 0, 0)), (17.4, (-0.3638, 0.006, 0.2275)), (4.8, (-0.0203, -0.0141, 0.070)),
        (0.82, (0, 0.019, 0)), (0.34, (0, 0, 0)), (0.09, (0, 0, 0.032))]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def dh(d, a, alpha_deg, theta=0.0):
    ca, sa = math.cos(math.radians(alpha_deg)), math.sin(math.radians(alpha_deg))
    ct, st = math.cos(theta), math.sin(theta)
    return [[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d], [0, 0, 0, 1]]


def clean(v):
    r = round(v * 1000, 9)  # mm, rounded away from floating noise
    return 0.0 if r == 0 else r


def main():
    t = [[1 if i == j else 0 for j in range(4)] for i in range(4)]
    frames = [t]
    for d, a, alpha in DH:
        t = matmul(t, dh(d, a, alpha))
        frames.append(t)
    for i in range(6):
        f = frames[i]
        point = [clean(f[r][3]) for r in range(3)]
        axis = [round(f[r][2], 12) + 0.0 for r in range(3)]
        print(f"j{i + 1}: point {point} mm, axis {axis}")
    f6 = frames[6]
    print("flange origin", [clean(f6[r][3]) for r in range(3)], "z", [round(f6[r][2], 12) + 0.0 for r in range(3)],
          "x", [round(f6[r][0], 12) + 0.0 for r in range(3)])
    for i, (m, r) in enumerate(MASS):
        if m == 0:
            continue
        f = frames[i + 1]
        com = [clean(f[k][3] + sum(f[k][j] * r[j] for j in range(3))) for k in range(3)]
        print(f"link {i + 1}: {m} kg, centre of mass {com} mm (base, zero position)")


if __name__ == "__main__":
    main()
