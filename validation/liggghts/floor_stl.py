"""ASCII STL of the silo floor: a square plate (side `width`, in the plane
z = 0, centred on the z axis) with a centred circular hole of diameter D0,
approximated by a regular polygon of the same area (`segments` sides, a
multiple of 4 so that the square's corners are vertices).

    python3 floor_stl.py [out.stl]      # scenes.SILO, default silo_floor.stl
"""

import sys

import numpy as np


def plate_with_hole(width, D0, segments=64):
    """Triangles (n, 3, 3) of the plate, normals +z."""
    assert segments % 4 == 0
    theta = 2*np.pi*np.arange(segments)/segments
    # polygon radius giving the circle's area: n/2 r^2 sin(2 pi/n) = pi R^2
    r = D0/2*np.sqrt(2*np.pi/(segments*np.sin(2*np.pi/segments)))
    direction = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    inner = r*direction
    # the same rays to the square's boundary (corners at 45 degrees)
    outer = width/2*direction/np.abs(direction).max(axis=1, keepdims=True)
    tris = []
    for i in range(segments):
        j = (i + 1) % segments
        tris.append([inner[i], outer[i], outer[j]])
        tris.append([inner[i], outer[j], inner[j]])
    tris = np.array(tris)
    return np.concatenate([tris, np.zeros(tris.shape[:2] + (1,))], axis=2)


def write_stl(path, triangles, name="floor"):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for t in triangles:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            n /= np.linalg.norm(n)
            f.write(f"  facet normal {n[0]:.9e} {n[1]:.9e} {n[2]:.9e}\n"
                    "    outer loop\n")
            for v in t:
                f.write(f"      vertex {v[0]:.9e} {v[1]:.9e} {v[2]:.9e}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")


if __name__ == "__main__":
    from scenes import SILO
    out = sys.argv[1] if len(sys.argv) > 1 else "silo_floor.stl"
    tris = plate_with_hole(SILO["width"], SILO["orifice"], SILO["orifice_segments"])
    write_stl(out, tris)
    area = 0.5*np.abs(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])[:, 2]).sum()
    hole = SILO["width"]**2 - area
    print(f"{out}: {len(tris)} triangles, hole area {hole:.6e} m2"
          f" (circle {np.pi/4*SILO['orifice']**2:.6e})")
