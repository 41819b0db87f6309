"""Writing the core's 3D D-form (``simulate`` result: vertices, triangles, piece per triangle)
as Wavefront OBJ (text, one group per piece) or binary STL (facet normals from the right-hand
rule, as the format requires)."""

import struct


def write_obj(path, vertices, triangles, piece, comment):
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(f"# {comment}\n")
        for x, y, z in vertices:
            fh.write(f"v {x:.9g} {y:.9g} {z:.9g}\n")
        for which, name in ((0, "piece_A"), (1, "piece_B")):
            fh.write(f"g {name}\n")
            for (i, j, k), p in zip(triangles, piece):
                if p == which:
                    fh.write(f"f {i + 1} {j + 1} {k + 1}\n")


def write_stl(path, vertices, triangles, comment):
    header = comment.encode("ascii", "replace")[:80].ljust(80, b" ")
    with open(path, "wb") as fh:
        fh.write(header)
        fh.write(struct.pack("<I", len(triangles)))
        for i, j, k in triangles:
            a, b, c = vertices[i], vertices[j], vertices[k]
            u = [b[n] - a[n] for n in range(3)]
            v = [c[n] - a[n] for n in range(3)]
            nx, ny, nz = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
            length = (nx * nx + ny * ny + nz * nz) ** 0.5 or 1.0
            fh.write(struct.pack("<12fH", nx / length, ny / length, nz / length, *a, *b, *c, 0))
