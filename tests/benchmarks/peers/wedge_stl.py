#!/usr/bin/env python3
"""Writes the inclined walls of a wedge hopper slab as an ASCII STL for a LIGGGHTS
`fix mesh/surface`, built as fullsim/dem/scene/wedge_hopper_slab.cpp builds its wedge mesh:
two planes from the outlet edges (x = +-W/2, z = 0) up to the bin (x = +-B/2, z = zb), cut
into strips about `strip` tall, spanning y from `y0` to `y1`. Lengths in metres.

    wedge_stl.py --semi-angle 30 --outlet 0.06 --bin 0.6 --y0 -0.003 --y1 0.0063 > wedge.stl
"""
import argparse
import math


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--semi-angle", type=float, required=True, help="from the vertical [deg]")
    p.add_argument("--outlet", type=float, required=True, help="outlet width W [m]")
    p.add_argument("--bin", type=float, required=True, help="bin width B [m]")
    p.add_argument("--y0", type=float, required=True, help="front edge [m]")
    p.add_argument("--y1", type=float, required=True, help="back edge [m]")
    p.add_argument("--strip", type=float, default=0.01, help="strip height [m]")
    a = p.parse_args()
    half_w, half_b = 0.5 * a.outlet, 0.5 * a.bin
    zb = (half_b - half_w) / math.tan(math.radians(a.semi_angle))
    strips = max(1, math.ceil(zb / a.strip))
    print("solid wedge")
    for side in (-1.0, 1.0):
        for k in range(strips):
            z0, z1 = zb * k / strips, zb * (k + 1) / strips
            x0 = side * (half_w + (half_b - half_w) * z0 / zb)
            x1 = side * (half_w + (half_b - half_w) * z1 / zb)
            quad = [(x0, a.y0, z0), (x1, a.y0, z1), (x1, a.y1, z1), (x0, a.y1, z0)]
            for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
                u = [tri[1][i] - tri[0][i] for i in range(3)]
                w = [tri[2][i] - tri[0][i] for i in range(3)]
                n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
                norm = math.sqrt(sum(c * c for c in n))
                print("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop".format(*(c / norm for c in n)))
                for v in tri:
                    print(f"      vertex {v[0]:.12g} {v[1]:.12g} {v[2]:.12g}")
                print("    endloop\n  endfacet")
    print("endsolid wedge")


if __name__ == "__main__":
    main()
