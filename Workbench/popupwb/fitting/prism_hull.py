"""The faces of a fitted prism from its corners, whatever their order: a prism is convex, so its
faces are those of the corners' convex hull. For drawing (the GUI overlay); headless."""

import itertools

import numpy as np


def hull_faces(points):
    """Faces of the convex hull of a few points (a prism's 6 or 8 corners, in any order), each a
    list of point indices counter-clockwise seen from outside: the planes through three points
    with every other point on their inner side, each plane once, its points ordered by angle."""
    p = np.asarray(points, dtype=float)
    scale = float(np.max(np.ptp(p, axis=0))) or 1.0
    tolerance = 1e-9 * scale
    centre = p.mean(axis=0)
    faces, planes = [], []
    for i, j, k in itertools.combinations(range(len(p)), 3):
        normal = np.cross(p[j] - p[i], p[k] - p[i])
        length = np.linalg.norm(normal)
        if length <= tolerance * scale:
            continue  # three points on a line
        normal /= length
        if normal @ (centre - p[i]) > 0:
            normal = -normal
        distances = (p - p[i]) @ normal
        if np.any(distances > tolerance):
            continue  # points on both sides: not a face
        if any(
            abs(normal @ n - 1) < 1e-9 and abs(normal @ (p[i] - q)) < tolerance for n, q in planes
        ):
            continue  # this face's plane is already met
        planes.append((normal, p[i]))
        on = [m for m in range(len(p)) if abs(distances[m]) <= tolerance]
        middle = p[on].mean(axis=0)
        u = p[on[0]] - middle
        u /= np.linalg.norm(u)
        v = np.cross(normal, u)
        angles = [np.arctan2((p[m] - middle) @ v, (p[m] - middle) @ u) for m in on]
        faces.append([on[m] for m in np.argsort(angles)])
    return faces
