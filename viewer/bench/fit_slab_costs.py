#!/usr/bin/env python3
"""Fits the slicer's cost weights (SlicingQuality.cpp, quadratureCost) to the fixed grids of
`volsg-bench --suite node|volumes --sweep --csv FILE` runs.

Per case and mode, ms/frame = a plane + b lean-sample + c general-sample + d (pre-integrated
sample | voxel-centre crossing) + e, by least squares weighted by 1/ms (relative error); the
weights are printed in units of the lean sample (b). Usage:
    /usr/bin/python3 viewer/bench/fit_slab_costs.py sweep-node.csv sweep-volumes.csv
"""
import csv
import math
import re
import sys

import numpy as np

# Box diagonals in L0 (the sweep sets numPlanes = ceil(planes/L0 x diagonal)); the node suite's
# cases by name, every other case a 64^3 cube.
DIAGONAL_L0 = {"chest-ct": 432.3, "ml256": 443.4}
SETTING = re.compile(r"([0-9.e-]+) planes/L0 x (\d+)(, (peaks|no peaks|pre-int))?$")


def rows(path):
    for r in csv.DictReader(open(path)):
        m = SETTING.match(r["setting"])
        if not m:
            continue
        scene = r["scene"]
        if scene.endswith(("-dvr", "-mip")):
            case, mode = scene.rsplit("-", 1)
        else:
            case, mode = scene, ("mip" if "mip" in scene else "dvr")
        per_l0, samples, kind = float(m.group(1)), int(m.group(2)), m.group(4) or ""
        planes = max(1, math.ceil(per_l0 * DIAGONAL_L0.get(case, 64 * math.sqrt(3))))
        yield dict(case=case, mode=mode, planes=planes, samples=samples, kind=kind,
                   spacing=1.0 / per_l0, ms=float(r["ms_per_frame"]))


def features(r):
    n, k = r["planes"], r["samples"]
    f = [n, 0.0, 0.0, 0.0, 1.0]  # plane, lean, general, pre-int or crossing, frame
    if r["mode"] == "dvr":
        if r["kind"] == "pre-int":
            f[3] = n * k
        elif k > 1:
            f[1] = n * k
        else:
            f[2] = n * k
    elif r["kind"] == "peaks":
        f[2] = n * k
        f[3] = n * (3.0 if k == 1 else 1.7 * r["spacing"])
    elif k > 1:
        f[1] = n * k
    else:
        f[2] = n * k
    return f


def main(paths):
    data = [r for p in paths for r in rows(p)]
    for key in sorted({(r["case"], r["mode"]) for r in data}):
        sub = [r for r in data if (r["case"], r["mode"]) == key]
        a = np.array([features(r) for r in sub])
        y = np.array([r["ms"] for r in sub])
        coef = np.linalg.lstsq(a / y[:, None], np.ones_like(y), rcond=None)[0]
        ratio = (a @ coef) / y
        lean = coef[1]
        last = "pre-int" if key[1] == "dvr" else "crossing"
        print(f"{key[0]} {key[1]}: {len(sub)} settings, plane {coef[0] / lean:.1f}, general "
              f"{coef[2] / lean:.2f}, {last} {coef[3] / lean:.2f} lean samples "
              f"(fit within {ratio.min():.2f}-{ratio.max():.2f})")


if __name__ == "__main__":
    main(sys.argv[1:])
