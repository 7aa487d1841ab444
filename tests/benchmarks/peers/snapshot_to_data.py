#!/usr/bin/env python3
"""Writes the first particle snapshot of a feedflow DEM run (particles.h5) as a LIGGGHTS /
LAMMPS `read_data` file for `atom_style granular`, so that a peer starts from the same grains.

    snapshot_to_data.py RUN/particles.h5 hopper_slab.data --density 390 \
        --box xlo xhi ylo yhi zlo zhi

Atoms: id (ours + 1, LIGGGHTS ids start at 1), type 1, diameter 2 R, the given density, the
position; Velocities: velocity and angular velocity. Reads the datasets with `h5dump -b`
(raw little-endian binary), so it needs only the HDF5 tools and the Python standard library.
Prints the particle count and mass.
"""
import argparse
import math
import os
import struct
import subprocess
import sys
import tempfile


def dataset(h5, path, fmt):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "raw.bin")
        subprocess.run(["h5dump", "-b", "LE", "-d", path, "-o", out, h5], check=True,
                       stdout=subprocess.DEVNULL)
        raw = open(out, "rb").read()
    size = struct.calcsize(fmt)
    return [struct.unpack_from("<" + fmt, raw, k * size)[0] for k in range(len(raw) // size)]


def first_snapshot(h5):
    listing = subprocess.run(["h5dump", "-n", h5], check=True, capture_output=True,
                             text=True).stdout
    groups = sorted({line.split()[1] for line in listing.splitlines()
                     if line.strip().startswith("group") and "/snapshots/step_" in line})
    if not groups:
        sys.exit(f"{h5}: no /snapshots/step_* group (not a feedflow particle snapshot file)")
    return groups[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("snapshots", help="particles.h5 of a feedflow DEM run")
    parser.add_argument("data", help="the read_data file to write")
    parser.add_argument("--density", type=float, required=True, help="grain density [kg/m^3]")
    parser.add_argument("--box", type=float, nargs=6, required=True,
                        metavar=("XLO", "XHI", "YLO", "YHI", "ZLO", "ZHI"), help="box [m]")
    parser.add_argument("--types", type=int, default=3, help="atom types in the box")
    a = parser.parse_args()

    g = first_snapshot(a.snapshots)
    x = dataset(a.snapshots, g + "/position", "d")
    v = dataset(a.snapshots, g + "/velocity", "d")
    w = dataset(a.snapshots, g + "/angular_velocity", "d")
    r = dataset(a.snapshots, g + "/radius", "d")
    ids = dataset(a.snapshots, g + "/id", "I")
    n = len(r)
    if len(x) != 3 * n or len(v) != 3 * n or len(w) != 3 * n or len(ids) != n:
        sys.exit(f"{a.snapshots}{g}: datasets of different lengths")
    mass = sum(a.density * 4.0 / 3.0 * math.pi * ri ** 3 for ri in r)
    b = a.box
    with open(a.data, "w") as f:
        f.write(f"feedflow snapshot {g} of {a.snapshots}: {n} grains, {mass:.9g} kg\n\n")
        f.write(f"{n} atoms\n{a.types} atom types\n\n")
        f.write(f"{b[0]:.17g} {b[1]:.17g} xlo xhi\n{b[2]:.17g} {b[3]:.17g} ylo yhi\n"
                f"{b[4]:.17g} {b[5]:.17g} zlo zhi\n\nAtoms\n\n")
        for k in range(n):
            f.write(f"{ids[k] + 1} 1 {2.0 * r[k]:.17g} {a.density:.17g} "
                    f"{x[3 * k]:.17g} {x[3 * k + 1]:.17g} {x[3 * k + 2]:.17g}\n")
        f.write("\nVelocities\n\n")
        for k in range(n):
            f.write(f"{ids[k] + 1} {v[3 * k]:.17g} {v[3 * k + 1]:.17g} {v[3 * k + 2]:.17g} "
                    f"{w[3 * k]:.17g} {w[3 * k + 1]:.17g} {w[3 * k + 2]:.17g}\n")
    print(f"{g}: {n} grains, {mass:.9g} kg -> {a.data}")


if __name__ == "__main__":
    main()
