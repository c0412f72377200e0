#!/usr/bin/env python3
"""Writes the mesh obstacles of configs/obstacles/ (closed surfaces, outward normals, in metres).

Each is drawn from a formula here, no third-party model:

  sphere.obj      a ball of radius 0.1 m: an icosahedron whose faces are split in four `--level`
                  times (4: 5,120 triangles), every vertex pushed out onto the sphere;
  round_table.obj a table of revolution: a top 0.9 m across and 3 cm thick whose rim is rounded
                  (radius 1.5 cm), on a column, 0.75 m high;
  dress_form.obj  a body of revolution with a dress form's proportions (bust, waist and hip
                  circumferences 88, 70 and 94 cm, at heights 1.25, 1.05 and 0.85 m of a 1.66 m
                  person: the size-38 measurements of EN 13402-3's table), from the hip down to the
                  neck, closed by flat caps.

Usage: tools/obstacle_meshes.py [--level N] [--out DIR]
"""
import argparse
import math
import os


def write_obj(path, vertices, faces, comment):
    with open(path, "w") as out:
        for line in comment.splitlines():
            out.write("# " + line + "\n")
        for v in vertices:
            out.write("v %.9g %.9g %.9g\n" % v)
        for f in faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def icosphere(radius, level):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(v):
        n = math.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    vertices = [unit(v) for v in vertices]
    for _ in range(level):
        middle = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                va, vb = vertices[a], vertices[b]
                vertices.append(unit(tuple((p + q) / 2 for p, q in zip(va, vb))))
                middle[key] = len(vertices) - 1
            return middle[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return [tuple(radius * c for c in v) for v in vertices], faces


def revolve(profile, sides):
    """The surface swept by `profile` [(r, z), ...] (from the bottom axis point up to the top axis
    point, r > 0 between) about the z axis, with `sides` segments; faces outward."""
    vertices = [(0.0, 0.0, profile[0][1])]
    rings = profile[1:-1]
    for r, z in rings:
        for k in range(sides):
            a = 2 * math.pi * k / sides
            vertices.append((r * math.cos(a), r * math.sin(a), z))
    vertices.append((0.0, 0.0, profile[-1][1]))
    top = len(vertices) - 1

    def ring(i, k):
        return 1 + i * sides + (k % sides)

    faces = []
    for k in range(sides):
        faces.append((0, ring(0, k + 1), ring(0, k)))
    for i in range(len(rings) - 1):
        for k in range(sides):
            faces.append((ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)))
            faces.append((ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)))
    last = len(rings) - 1
    for k in range(sides):
        faces.append((top, ring(last, k), ring(last, k + 1)))
    return vertices, faces


def round_table_profile():
    top_radius, thickness, rim, height, column = 0.45, 0.03, 0.015, 0.75, 0.05
    profile = [(0.0, 0.0), (0.25, 0.0), (0.25, 0.02), (column, 0.04), (column, height - thickness)]
    profile.append((top_radius - rim, height - thickness))
    # The rim: a half-round of radius `rim` around (top_radius − rim, height − thickness / 2).
    centre = (top_radius - rim, height - thickness / 2)
    for k in range(1, 12):
        a = -math.pi / 2 + math.pi * k / 12
        profile.append((centre[0] + rim * math.cos(a), centre[1] + rim * math.sin(a)))
    profile += [(top_radius - rim, height), (0.0, height)]
    return profile


def dress_form_profile():
    # (circumference, height) from the hip to the neck; r = C / 2π.
    girth = [(0.90, 0.78), (0.94, 0.85), (0.88, 0.95), (0.70, 1.05), (0.76, 1.15), (0.88, 1.25),
             (0.86, 1.33), (0.60, 1.42), (0.36, 1.47), (0.34, 1.55)]
    points = [(c / (2 * math.pi), z) for c, z in girth]
    # A smooth profile: Catmull–Rom through the points, 8 per span.
    smooth = []
    for i in range(len(points) - 1):
        p0 = points[max(i - 1, 0)]
        p1, p2 = points[i], points[i + 1]
        p3 = points[min(i + 2, len(points) - 1)]
        for s in range(8):
            t = s / 8
            smooth.append(tuple(
                0.5 * (2 * b + (-a + c) * t + (2 * a - 5 * b + 4 * c - d) * t * t +
                       (-a + 3 * b - 3 * c + d) * t ** 3)
                for a, b, c, d in zip(p0, p1, p2, p3)))
    smooth.append(points[-1])
    return [(0.0, points[0][1])] + smooth + [(0.0, points[-1][1])]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--level", type=int, default=4, help="the sphere's subdivisions")
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "configs",
                                                       "obstacles"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    v, f = icosphere(0.1, args.level)
    write_obj(os.path.join(args.out, "sphere.obj"), v, f,
              "A ball of radius 0.1 m (%d triangles): tools/obstacle_meshes.py --level %d"
              % (len(f), args.level))
    v, f = revolve(round_table_profile(), 96)
    write_obj(os.path.join(args.out, "round_table.obj"), v, f,
              "A round table 0.9 m across, 0.75 m high, its rim rounded: tools/obstacle_meshes.py")
    v, f = revolve(dress_form_profile(), 64)
    write_obj(os.path.join(args.out, "dress_form.obj"), v, f,
              "A dress form's torso (EN 13402-3 size 38): tools/obstacle_meshes.py")


if __name__ == "__main__":
    main()
